#pragma once
// Tutorial 02's oracles: what the check compares your functions with. Their answers are
// data (oracle_data.txt, oracle_data.h), recorded by the instructor's oracles: a search
// along the segment in long double, and points sampled along the new segment.
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {
/// The distance from p to the segment a-b.
double segmentGap(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b);
/// Is the segment p-q inside the capsule of `radius` around a-b (17 points spread along it
/// within the radius)?
bool capsuleContains(const rc::Vec3& a, const rc::Vec3& b, double radius, const rc::Vec3& p, const rc::Vec3& q);
/// The gap from the segment a-b to the nearest sphere but `hit`.
double sphereGap(const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a, const rc::Vec3& b);
}  // namespace tutorial
