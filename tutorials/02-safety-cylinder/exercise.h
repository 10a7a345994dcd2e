#pragma once
// Tutorial 02: the cylinder of safety.
#include "geometry/ray.h"

namespace tutorial {

// [declaration]
/// Distance from point `p` to the segment from `a` to `b` (which may be a single point,
/// `a == b`). A sphere (c, r) stays out of the capsule of radius R around the segment
/// when segmentDistance(c, a, b) - r > R.
double segmentDistance(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b);
// [declaration]

}  // namespace tutorial
