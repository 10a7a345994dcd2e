// Tutorial 06: the exercise as shipped, a READ-ONLY copy of exercise.cpp. Do not edit it:
// your work goes in exercise.cpp. The docs quote this file and CI checks that it still fails.
#include <cmath>

#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

// [stub]
Roots stableRoots(const rc::Ray& ray, const rc::Sphere& s) {
    // TODO: this is the textbook formula. It is right on paper and wrong in doubles when
    // the sphere is small and far away: b*b and c are huge and nearly equal. Make it stable.
    const rc::Vec3 f = ray.o - s.c;
    const double b = glm::dot(f, ray.d);
    const double c = glm::dot(f, f) - s.r * s.r;
    const double disc = b * b - c;
    if (disc < 0.0) return {};
    const double root = std::sqrt(disc);
    return {true, -b - root, -b + root};
}
// [stub]

}  // namespace tutorial
