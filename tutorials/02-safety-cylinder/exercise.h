#pragma once
// Tutorial 02: the cylinder of safety.
#include <vector>

#include "geometry/intersection.h"
#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {

// [declaration]
/// Distance from point `p` to the segment from `a` to `b` (which may be a single point,
/// `a == b`).
double segmentDistance(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b);

/// The radius of the cylinder of safety around the segment from `a` to `b`, a ray that
/// hit sphere `hit` of `spheres`: the largest radius whose capsule no *other* sphere
/// enters. Negative when another sphere already meets the segment; rc::kNoHit (infinity)
/// when there is no other sphere.
double safetyRadius(const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a, const rc::Vec3& b);

/// Does the segment from `p` to `q` lie inside the capsule of radius `radius` around the
/// segment from `a` to `b`? (A cache hit needs the new ray's segment inside.)
bool insideCapsule(const rc::Vec3& p, const rc::Vec3& q, const rc::Vec3& a, const rc::Vec3& b, double radius);
// [declaration]

}  // namespace tutorial
