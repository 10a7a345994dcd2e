#pragma once
// Tutorial 03: blocker cones, the convex hull of two spheres.
#include "geometry/sphere.h"

namespace tutorial {

// [declaration]
/// Signed distance from `p` to the convex hull of spheres `a` and `b` (a point is a
/// sphere of radius 0): exact when `p` is outside the hull, negative (or zero) inside.
/// The hull is both spheres and the tangent cone between them; when one sphere holds
/// the other, it is the larger sphere.
double hullDistance(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b);
// [declaration]

}  // namespace tutorial
