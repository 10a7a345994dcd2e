#pragma once
// Tutorial 06: numerical stability of the ray-sphere intersection.
#include "geometry/intersection.h"

namespace tutorial {

// [declaration]
/// Both roots t0 <= t1 of |o + t d - c|^2 = r^2 for a unit direction d, or hit = false.
/// Must stay accurate for small spheres far away, where the textbook formula fails.
rc::SphereRoots stableRoots(const rc::Ray& ray, const rc::Sphere& s);
// [declaration]

}  // namespace tutorial
