#pragma once
/// \file
/// \brief The cylinder of safety (Speer, DeRose, Barsky 1985): a capsule around the last
/// ray segment that no other surface enters. Its measures are tutorial 02's hole
/// (geometry/safety_cylinder.cpp).
#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace rc {

/// Distance from point `p` to segment `a`-`b` (`a == b`: a single point).
double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b);

/// The radius of the cylinder of safety around the segment `a`-`b`, a ray that hit sphere
/// `hit` of `spheres`: the largest radius whose capsule no *other* sphere enters. Negative
/// when another sphere already meets the segment; kNoHit (infinity) when there is no other
/// sphere.
double safetyRadius(const std::vector<Sphere>& spheres, int hit, const Vec3& a, const Vec3& b);

/// A capsule: every point within `radius` of the segment `a`-`b`.
struct SafetyCylinder {
    Vec3 a{0.0};
    Vec3 b{0.0};
    double radius = -1.0;  ///< negative: empty

    /// Distance from `p` to the segment.
    double distance(const Vec3& p) const { return segmentDistance(p, a, b); }

    /// Does the segment `p`-`q` lie inside? (A cache hit needs the new ray's segment inside.)
    bool contains(const Vec3& p, const Vec3& q) const;
};

}  // namespace rc
