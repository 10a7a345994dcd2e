#pragma once
// Tutorial 06's oracles: what the check compares your roots with. Their answers are data
// (oracle_data.txt, oracle_data.h), recorded by the instructor's oracles: roots found
// without the quadratic formula, in extended precision.
#include <vector>

#include "geometry/intersection.h"
#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {
/// Both roots of the ray's equation with sphere `s`, rounded to doubles; hit = false when
/// the ray's line misses it.
rc::SphereRoots oracleSphereRoots(const rc::Ray& ray, const rc::Sphere& s);
/// The sphere the ray meets first by the oracle's roots (its near root when positive,
/// else its far one; equal distances to the lower index), -1 for none.
int oracleFirstHit(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres);
}  // namespace tutorial
