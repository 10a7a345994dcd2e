#pragma once
/// \file
/// \brief What a render counts: rays, intersection tests, cache hits and misses by reason.
#include <array>
#include <cstdint>
#include <string_view>

#include "search/ray_kind.h"

namespace rc {

/// How a ray's nearest hit was found.
enum class Decision : std::uint8_t {
    Uncached,  ///< no cache: complete search
    Hit,       ///< the cache answered with the object it held
    Miss,      ///< the cache held something else (see MissReason)
};
std::string_view toString(Decision d);

/// Why a cache missed.
enum class MissReason : std::uint8_t {
    None,           ///< not a miss
    Cold,           ///< the entry was empty
    Flushed,        ///< a miss at the parent flushed the entry
    OriginChanged,  ///< the entry was made for rays leaving another object
    TargetMissed,   ///< the ray does not hit the cached object
    BlockerHit,     ///< a potential blocker is hit first: a new object, found without a search
    LeftCylinder,   ///< the ray leaves the cylinder of safety
    LeftCone,       ///< an empty eye ray leaves the cone known to be empty
};
inline constexpr int kMissReasons = 8;
std::string_view toString(MissReason r);

/// Machine-independent counts of one render.
struct Counters {
    std::array<std::uint64_t, kRayKinds> rays{};  ///< rays traced, by kind
    std::uint64_t primaryHits = 0;        ///< eye rays that hit an object (SPD's tables count these)
    std::uint64_t intersectionTests = 0;  ///< every ray-object test, cached or not
    std::uint64_t completeSearches = 0;   ///< searches over the whole scene
    std::uint64_t cylinderTests = 0;      ///< capsule containment tests
    std::uint64_t coneTests = 0;          ///< empty-cone tests of eye rays
    std::uint64_t hits = 0;
    std::uint64_t misses = 0;
    std::array<std::uint64_t, kMissReasons> missReasons{};
    std::uint64_t deferrals = 0;  ///< breadth-first: cheap tests that failed, pixel deferred
    std::uint64_t verifyDisagreements = 0;
    std::uint64_t blockerListsBuilt = 0;
    std::uint64_t blockerListEntries = 0;  ///< summed over built lists
    std::uint64_t blockerListMax = 0;
    std::uint64_t hullTests = 0;        ///< sphere-versus-hull tests made building lists
    std::uint64_t cylindersBuilt = 0;   ///< safety cylinders computed
    std::uint64_t conesBuilt = 0;       ///< blocker+: empty cones of eye rays computed
    /// Rays that left a cylinder of safety before it was measured: an object nearer the kept
    /// segment than the ray strays was found (or already known), so it was not built for them
    std::uint64_t cylindersRuledOut = 0;
    /// Blocker+ in front of a cheap search: rays searched at once, their path having stepped aside
    std::uint64_t steppedAside = 0;
    /// Blocker+dir: misses answered from a list of the objects in their direction, not by a
    /// complete search (DirectionLists)
    std::uint64_t directionSearches = 0;
    std::uint64_t directionListsBuilt = 0;
    std::uint64_t directionListEntries = 0;  ///< summed over built lists

    std::uint64_t totalRays() const { return rays[0] + rays[1] + rays[2] + rays[3]; }
    Counters& operator+=(const Counters& o);
    bool operator==(const Counters&) const = default;
};

}  // namespace rc
