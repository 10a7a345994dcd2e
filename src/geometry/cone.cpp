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
    // The hull works out the cone once (its constructor is tutorial 03's hole)
    const Hull hull(a, b);
    return hull.nested() ? 0.0 : pm::asin(hull.sinHalfAngle());
}

}  // namespace rc
