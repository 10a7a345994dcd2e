#pragma once
/// \file
/// \brief The cylinder of safety (Speer, DeRose, Barsky 1985): a capsule around the last
/// ray segment that no other surface enters.
#include "geometry/ray.h"

namespace rc {

/// A capsule: every point within `radius` of the segment `a`-`b`.
struct SafetyCylinder {
    Vec3 a{0.0};
    Vec3 b{0.0};
    double radius = -1.0;  ///< negative: empty

    /// Distance from `p` to the segment.
    double distance(const Vec3& p) const;

    /// Does the segment `p`-`q` lie inside? The capsule is convex, so checking both
    /// endpoints is enough.
    bool contains(const Vec3& p, const Vec3& q) const {
        return distance(p) <= radius && distance(q) <= radius;
    }
};

/// Distance from point `p` to segment `a`-`b`.
double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace rc
