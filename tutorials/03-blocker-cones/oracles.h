#pragma once
// Tutorial 03's oracles: what the check compares your hull with. Their answers are data
// (oracle_data.txt, oracle_data.h), recorded by the instructor's oracles, which compute the
// hull apart from the library, in long double.
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {
/// The distance from p to the convex hull of spheres a and b when p is outside it,
/// negative inside it.
double hullGap(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b);
/// The hull of a and b in the plane z = 0 on a w x h grid of pixel centres, the pixel
/// (x, y) at (x0 + (x + 0.5) scale, y0 - (y + 0.5) scale): one character per pixel, row
/// by row, '1' inside the hull (hullGap <= 0), '0' outside.
std::string hullSlice(const rc::Sphere& a, const rc::Sphere& b, int w, int h, double x0, double y0, double scale);
/// The ids of the spheres that meet the hull of a and b by more than rounding
/// (hullGap(c_j) <= r_j - 1e-9), in order, `skip` left out.
std::vector<int> blockerList(const rc::Sphere& a, const rc::Sphere& b, const std::vector<rc::Sphere>& spheres, int skip);
}  // namespace tutorial
