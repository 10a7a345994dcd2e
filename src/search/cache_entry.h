#pragma once
/// \file
/// \brief A cache entry: what one ray-tree path's cache holds, for every strategy.
#include <cstdint>

#include "geometry/safety_cylinder.h"
#include "search/query.h"

namespace rc {

/// What a cache entry holds: the state every strategy shares (state, origin, object), then
/// each strategy's own, written by that strategy only:
/// - the cylinder of safety (CylinderOfSafety; the cylinder cache, and the blocker caches'
///   rays that hit nothing): cylinder, pending, cylinderBelow, nearObject;
/// - blocker+'s empty cone of eye rays that hit nothing (BlockerCache): coneAxis, coneAngle,
///   coneCos, coneSin, and pending while it is not built;
/// - the blocker caches' list of potential blockers (BlockerCache): list; blocker+dir's
///   direction list: directions;
/// - the window of a path that may step aside (AsideBlockerCache): tried, spared, asideFor,
///   failed.
///
/// One flat entry for every strategy: the cache tree flushes and clears entries, checkpoints
/// copy them and the view draws them whatever the strategy, and a lookup reads one entry.
struct CacheEntry {
    enum class State : std::uint8_t { Empty, Flushed, Loaded };
    State state = State::Empty;
    RayOrigin origin;          ///< the entry answers rays leaving this origin only
    int object = -1;           ///< the object last hit, -1 for nothing
    SafetyCylinder cylinder;   ///< around the last segment (radius < 0: none)
    Vec3 coneAxis{0.0};        ///< empty cone around the last empty eye ray
    double coneAngle = -1.0;   ///< its half-angle in radians (< 0: none)
    double coneCos = 2.0;      ///< cos(coneAngle), for the test without trigonometry
    double coneSin = 0.0;      ///< sin(coneAngle)
    bool pending = false;      ///< cylinder or cone not built yet: built when the entry is next used
    /// While the cylinder is pending: its radius, once measured, is known to be below this
    double cylinderBelow = kNoHit;
    /// The object that set the last cylinder's radius, or ruled it out (-1: none)
    int nearObject = -1;
    /// Blocker caches: the number of the list its last ray tested (BlockerLists::get)
    std::uint32_t list = std::uint32_t(-1);
    /// Blocker+dir: the number of the direction list its last miss tested (DirectionLists::get)
    std::uint32_t directions = std::uint32_t(-1);
    /// Blocker+ in front of a cheap search: lookups in the current window, and how many of
    /// them were answered without a search; and how many rays are still to search at once
    std::uint16_t tried = 0, spared = 0, asideFor = 0;
    /// Windows failed in a row: each doubles the rays stepped aside for (AsideBlockerCache)
    std::uint8_t failed = 0;
};

}  // namespace rc
