#pragma once
/// \file
/// \brief The cylinder of safety (Speer, DeRose, Barsky 1985): a capsule around the last
/// ray segment that no other surface enters.
#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/ray.h"

namespace rc {

/// Distance from point `p` to segment `a`-`b`. Inline: a cache measures two per ray.
inline double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// A capsule: every point within `radius` of the segment `a`-`b`.
struct SafetyCylinder {
    Vec3 a{0.0};
    Vec3 b{0.0};
    double radius = -1.0;  ///< negative: empty

    /// Distance from `p` to the segment.
    double distance(const Vec3& p) const { return segmentDistance(p, a, b); }

    /// Does the segment `p`-`q` lie inside? The capsule is convex, so checking both
    /// endpoints is enough.
    bool contains(const Vec3& p, const Vec3& q) const {
        return distance(p) <= radius && distance(q) <= radius;
    }
};

}  // namespace rc
