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

double intersectSphere(const Ray& ray, const Sphere& s, Start start) {
    // [sphere-start]
    // A ray leaving a sphere's surface outward cannot meet that sphere again
    if (start == Start::Leaving) return kNoHit;
    const SphereRoots roots = sphereRootsStable(ray, s);
    if (!roots.hit) return kNoHit;
    // A ray entering through the surface meets the sphere again at the far root
    if (start == Start::Entering) return roots.t1 > 0.0 ? roots.t1 : kNoHit;
    if (roots.t0 > 0.0) return roots.t0;
    return roots.t1 > 0.0 ? roots.t1 : kNoHit;
    // [sphere-start]
}

}  // namespace rc
