#pragma once
/// \file
/// \brief What made a cache miss: the entry the ray found, as the ray before it at the
/// same ray-tree path left it.
#include "geometry/safety_cylinder.h"
#include "view/ray_focus.h"

namespace rc {

/// The cause of the miss of a ray in focus, for the overlays to draw.
struct MissCause {
    MissReason reason = MissReason::None;
    int cachedEvent = -1;   ///< the last ray at the same path before it: its answer was cached (-1: none)
    int cachedObject = -1;  ///< the object that entry held: the target missed (-1: nothing)
    int blocker = -1;       ///< blocker_hit: the listed potential blocker hit first
    int loadedEvent = -1;   ///< the ray whose miss loaded the entry (its cylinder's or cone's ray)
    SafetyCylinder cylinder;  ///< left_cylinder: the cylinder of safety the ray left (radius < 0: none)
    bool valid() const { return reason != MissReason::None && cachedEvent >= 0; }
};

/// Events searched back for the ray before: a miss's cause is near it in every order.
inline constexpr int kMissCauseReach = 1 << 18;

/// The cause of `f`'s miss (reason None when `f` is not a miss, or its entry's ray lies
/// further back than kMissCauseReach events).
MissCause missCauseOf(const SessionState& s, const RayFocus& f);

}  // namespace rc
