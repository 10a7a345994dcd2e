#include "geometry/safety_cylinder.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace rc {

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double SafetyCylinder::distance(const Vec3& p) const { return segmentDistance(p, a, b); }

}  // namespace rc
