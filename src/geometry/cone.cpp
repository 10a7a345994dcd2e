#include "geometry/cone.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace rc {

double hullDistance(const Vec3& p, const Sphere& a, const Sphere& b) {
    // [hull-distance]
    const Vec3 axis = b.c - a.c;
    const double D = glm::length(axis);
    // One sphere inside the other: the hull is the larger sphere
    if (D <= std::abs(a.r - b.r)) {
        const Sphere& big = (a.r >= b.r) ? a : b;
        return glm::length(p - big.c) - big.r;
    }
    // Work in the half-plane through the axis: x along it, y away from it
    const Vec3 u = axis / D;
    const Vec3 ap = p - a.c;
    const double x = glm::dot(ap, u);
    const double y = glm::length(ap - x * u);
    // The tangent line touches A at ra*n and B at (D,0) + rb*n, with n = (s, c)
    const double s = (a.r - b.r) / D;
    const double c = std::sqrt(std::max(0.0, 1.0 - s * s));
    // Position along the tangent segment decides which piece of the boundary is nearest
    const double along = (x - a.r * s) * c - (y - a.r * c) * s;
    if (along < 0.0) return std::sqrt(x * x + y * y) - a.r;
    if (along > D * c) return std::sqrt((x - D) * (x - D) + y * y) - b.r;
    return x * s + y * c - a.r;
    // [hull-distance]
}

bool meetsHull(const Sphere& s, const Sphere& a, const Sphere& b, double slack) {
    return hullDistance(s.c, a, b) <= s.r + slack;
}

double hullHalfAngle(const Sphere& a, const Sphere& b) {
    const double D = glm::length(b.c - a.c);
    if (D <= std::abs(a.r - b.r)) return 0.0;
    return std::asin((a.r - b.r) / D);
}

}  // namespace rc
