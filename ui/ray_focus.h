#pragma once
/// \file
/// \brief The ray an overlay is drawn for: the one being traced, or one of a selected pixel.
#include <optional>

#include "event_record.h"
#include "session_state.h"

namespace rcgui {

/// One ray, with what the overlays need to know about it.
struct RayFocus {
    int pixel = 0;
    int node = 0;         ///< ray-tree path
    rc::RayKind kind = rc::RayKind::Primary;
    int light = -1;       ///< shadow rays: the light
    rc::RayOrigin origin;
    int hit = -1;         ///< object hit, -1 for nothing
    rc::Ray ray;
    double t = -1.0;      ///< hit distance, < 0 for none
    double tmax = -1.0;   ///< shadow rays: distance to the light
    bool current = false; ///< the ray being traced (its path's cache entry is the active one)
    bool deferred = false;

    /// Where the ray's segment ends: its hit, its light, or where it leaves the scene.
    rc::Vec3 segmentEnd(const rc::Scene& scene) const;

    /// The ray of the last trace event, if any.
    static std::optional<RayFocus> ofCurrent(const SessionState& s);
    /// The ray of recorded event `index`.
    static RayFocus ofEvent(const SessionState& s, int index);
};

/// The Speer-DeRose-Barsky cylinder of safety around a ray's segment: the largest
/// capsule no other object's bounding sphere enters (radius < 0 if none).
rc::SafetyCylinder cylinderAround(const rc::Scene& scene, const RayFocus& f);

/// The widest cone of eye rays around `f`'s direction that no bounding sphere enters,
/// as the blocker cache builds it for an eye ray that hits nothing (< 0: none).
double emptyConeAround(const rc::Scene& scene, const RayFocus& f);

}  // namespace rcgui
