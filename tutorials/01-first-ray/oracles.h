#pragma once
// Tutorial 01's oracle: what the check compares your search with. Its answers are data
// (oracle_data.txt, oracle_data.h), recorded by the instructor's oracle: every sphere's
// roots found without the quadratic formula, in extended precision, the nearest in front
// taken.
#include <vector>

#include "geometry/sphere.h"
#include "search/query.h"

namespace tutorial {
/// The nearest hit of query q among `spheres` (sphere j is object j), with RayCache's
/// rules: hits at tmax or beyond do not count, a ray leaving the surface it starts on
/// cannot meet it again, a ray entering it meets it at its far root; equal distances go to
/// the lower id. `ambiguous` is set when a root lies within rounding of 0 or of tmax;
/// `tests` to the number of intersection tests the complete search counts for q.
rc::Answer oracleNearest(const std::vector<rc::Sphere>& spheres, const rc::Query& q, bool& ambiguous, long& tests);
}  // namespace tutorial
