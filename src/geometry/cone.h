#pragma once
/// \file
/// \brief The convex hull of two spheres ("round cone"), where blockers must lie.
///
/// Any segment from a point of sphere A to a point of sphere B lies in the convex hull
/// of A and B: both spheres plus their common external tangent cone. A point (the eye,
/// a light) is a sphere of radius 0, so eye-to-sphere and light cones are the same
/// shape. One sphere inside the other gives the larger sphere.
#include "geometry/sphere.h"

namespace rc {

/// The hull of two spheres, with what its distance function needs worked out once: many
/// spheres are measured against one hull when a blocker list is built.
class Hull {
public:
    Hull(const Sphere& a, const Sphere& b);
    /// Signed distance from `p`: exact outside the hull, negative inside it.
    double distance(const Vec3& p) const;
    /// One sphere inside the other: the hull is the larger sphere.
    bool nested() const { return nested_; }
    /// The sine of the tangent cone's half-angle, as the constructor works it out.
    double sinHalfAngle() const { return s_; }

private:
    Sphere a_, b_;
    bool nested_;  ///< one sphere inside the other: the hull is the larger, a_
    Vec3 u_{0.0};  ///< unit axis from a to b
    double D_ = 0.0, s_ = 0.0, c_ = 0.0;
};

/// Signed distance from `p` to the hull of spheres `a` and `b`: exact outside the
/// hull, negative inside it.
double hullDistance(const Vec3& p, const Sphere& a, const Sphere& b);

/// Does sphere `s` meet the hull of `a` and `b`? `slack` widens the test (a list may
/// hold extra spheres, never miss one).
bool meetsHull(const Sphere& s, const Sphere& a, const Sphere& b, double slack);

/// Half-angle (radians) of the tangent cone of two spheres, from their Hull (tutorial 03's
/// hole). Negative when `b` is the larger one; 0 for equal radii (a cylinder) and for nested
/// spheres.
double hullHalfAngle(const Sphere& a, const Sphere& b);

}  // namespace rc
