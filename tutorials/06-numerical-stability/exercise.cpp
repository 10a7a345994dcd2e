// Tutorial 06, your exercise: make the ray-sphere roots stable. This file is yours to edit. Check it with
//   cmake --build build --target tutorial-06      (or: ctest --preset student -R 06)
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
