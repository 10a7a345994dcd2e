#include "geometry/cone.h"
#include "geometry/portable_math.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rc {

// Hull::Hull() and Hull::distance(): geometry/sphere_hull.cpp (tutorial 03's hole)

double hullDistance(const Vec3& p, const Sphere& a, const Sphere& b) { return Hull(a, b).distance(p); }

bool meetsHull(const Sphere& s, const Sphere& a, const Sphere& b, double slack) {
    return hullDistance(s.c, a, b) <= s.r + slack;
}

double hullHalfAngle(const Sphere& a, const Sphere& b) {
    const double D = glm::length(b.c - a.c);
    if (D <= std::abs(a.r - b.r)) return 0.0;
    return pm::asin((a.r - b.r) / D);
}

}  // namespace rc
