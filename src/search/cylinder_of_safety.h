#pragma once
/// \file
/// \brief The cylinder of safety as a cache keeps it (Speer, DeRose, Barsky 1985): around
/// the entry's last segment, measured only once a ray may fit in it.
#include "search/cache_strategy.h"

namespace rc {

/// Keeps, builds and tests the cylinder of safety of a cache entry (CacheEntry::cylinder,
/// pending, cylinderBelow, nearObject). The cylinder cache answers every ray with it; the
/// paper's blocker cache answers the rays that hit nothing with it, and blocker+ the rays
/// from an object that hit nothing.
class CylinderOfSafety {
public:
    CylinderOfSafety(const Scene& scene, const CompleteSearch& search);
    /// Keeps the segment of `q` ending at `a`; its cylinder is built when first needed.
    void keep(const Query& q, const Answer& a, CacheEntry& e) const;
    /// Builds the cylinder of safety around the kept segment (e.cylinder.a to b).
    void build(CacheEntry& e, Counters& n) const;
    /// Tests the cached object and the cylinder of safety, built (if pending) only when
    /// the new segment could fit in it.
    Lookup probe(const Query& q, CacheEntry& e, Counters& n) const;

private:
    /// The end of the segment a query covers: its hit, its light, or where it leaves
    /// the scene's bounding sphere.
    Vec3 segmentEnd(const Query& q, const Answer& a) const;
    /// Builds a pending cylinder for a new segment p-q that strays `need` from the kept
    /// one, unless an object nearer than that shows it too narrow (e.cylinderBelow).
    void buildFor(CacheEntry& e, double need, Counters& n) const;

    const Scene& scene_;
    const CompleteSearch& search_;
    double slack_;  ///< a few ulps of the scene's size: shrinks the cylinders
};

}  // namespace rc
