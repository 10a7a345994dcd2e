#pragma once
/// \file
/// \brief A compact copy of one rc::TraceEvent, small enough to keep for every ray.
#include <cstdint>

#include "trace/trace_event.h"

namespace rc {

/// One traced (or deferred) ray, as the GUI keeps it: much less than the full event, and
/// less again once coded in the recorder's rc::EventLog, so a whole render (millions of
/// events) fits in memory. The direction is kept
/// as two 16-bit octahedral coordinates (within about 1e-4 radians), and a shadow ray's
/// length is not kept: it is the distance from its origin to its light.
struct EventRecord {
    enum Flags : std::uint8_t { Deferred = 1, Searched = 2, Inside = 4 };

    std::int32_t step = 0;     ///< rays committed before this one
    std::int32_t pixel = 0;    ///< y * width + x
    std::int32_t node = 0;     ///< ray-tree path in the cache tree
    std::int32_t hit = -1;     ///< object hit, -1 for nothing
    std::int32_t origin = -1;  ///< object the ray leaves, -1 for the eye
    std::int32_t tests = 0;    ///< ray-object tests of the lookup
    std::int32_t region = 0;   ///< breadth-first region when traced (0: none)
    std::int32_t previous = -1;  ///< the pixel's previous event, -1 for none
    std::uint8_t kind = 0;     ///< rc::RayKind
    std::uint8_t decision = 0; ///< rc::Decision
    std::uint8_t reason = 0;   ///< rc::MissReason
    std::uint8_t flags = 0;
    float o[3] = {0, 0, 0};    ///< ray origin
    std::int16_t d[2] = {0, 0};  ///< ray direction, octahedral
    float t = -1.0f;           ///< hit distance, < 0 for none

    bool deferred() const { return flags & Deferred; }
    rc::RayKind rayKind() const { return rc::RayKind(kind); }
    rc::Decision rayDecision() const { return rc::Decision(decision); }
    rc::MissReason missReason() const { return rc::MissReason(reason); }
    rc::Vec3 rayOrigin() const { return {o[0], o[1], o[2]}; }
    rc::Vec3 rayDirection() const;

    /// Copies what the GUI needs from `e`.
    static EventRecord from(const rc::TraceEvent& e, int region, int previous);
    /// Sets o and d from `ray`, as from() does.
    void setRay(const rc::Ray& ray);
    /// Sets t from a lookup's answer (`known`: whether the lookup gave one), as from() does.
    void setDistance(bool known, const rc::Answer& a);
};

}  // namespace rc
