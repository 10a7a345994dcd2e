#include "geometry/intersection.h"

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace rc {

// sphereRootsStable(): geometry/stable_roots.cpp (tutorial 06's hole)
SphereRoots sphereRootsTextbook(const Ray& ray, const Sphere& s) {
    // [textbook-roots]
    const Vec3 f = ray.o - s.c;
    const double b = glm::dot(f, ray.d);
    const double c = glm::dot(f, f) - s.r * s.r;
    const double disc = b * b - c;  // two large, nearly equal squares
    if (disc < 0.0) return {};
    const double root = std::sqrt(disc);
    return {true, -b - root, -b + root};
    // [textbook-roots]
}

// intersectSphere(): geometry/stable_roots.cpp, beside the roots it inlines

}  // namespace rc
