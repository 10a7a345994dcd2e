#pragma once
/// \file
/// \brief A ray-scene query and its answer: the nearest object hit, and where.
#include "geometry/intersection.h"
#include "scene/scene.h"
#include "search/counters.h"

namespace rc {

/// One nearest-hit question. Shadow rays are asked the same question, limited to the
/// distance of their light (`tmax`), so a cached and an uncached answer can be compared
/// object for object.
struct Query {
    Ray ray;
    double tmax = kNoHit;  ///< hits at or beyond tmax do not count
    RayOrigin origin;      ///< where the ray starts
    RayKind kind = RayKind::Primary;
    int light = -1;  ///< shadow rays: the light they travel to
};

/// The nearest object hit (or -1) and its distance (or kNoHit).
struct Answer {
    int object = -1;
    double t = kNoHit;
    bool operator==(const Answer&) const = default;
};

/// The order every search agrees on: nearer first, then the lower object id, so that
/// cached and complete searches break ties alike.
inline bool nearer(double t, int id, const Answer& than) {
    return t < than.t || (t == than.t && id < than.object);
}

}  // namespace rc
