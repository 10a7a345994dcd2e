// Tutorial 02, the reference solution.
#include <algorithm>

#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

// [solution]
double segmentDistance(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b) {
    const rc::Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    // The nearest point is a + t (b - a), with t clamped to the segment
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}
// [solution]

}  // namespace tutorial
