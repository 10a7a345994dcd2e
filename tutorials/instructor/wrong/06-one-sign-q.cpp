// Tutorial 06, a wrong answer the check must reject: q = -b + sqrt(disc) whatever the sign of b
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"

namespace rc {

SphereRoots sphereRootsStable(const Ray& ray, const Sphere& s) {
    const rc::Vec3 f = ray.o - s.c;
    const double b = glm::dot(f, ray.d);
    // r^2 - |l|^2 with l the centre's perpendicular offset: no large squares cancel
    const rc::Vec3 l = f - b * ray.d;
    const double disc = s.r * s.r - glm::dot(l, l);
    if (disc < 0.0) return {};
    // q = -b - sign(b) sqrt(disc) adds two numbers of the same sign
    const double q = -b + std::sqrt(disc);
    const double c = glm::dot(f, f) - s.r * s.r;
    double t0 = q != 0.0 ? c / q : 0.0, t1 = q;  // Vieta: t0 t1 = c
    if (t0 > t1) std::swap(t0, t1);
    return {true, t0, t1};
}

// Unchanged from the exercise as shipped: the nearest root a ray can hit
double intersectSphere(const Ray& ray, const Sphere& s, Start start) {
    if (start == Start::Leaving) return kNoHit;
    const SphereRoots roots = sphereRootsStable(ray, s);
    if (!roots.hit) return kNoHit;
    if (start == Start::Entering) return roots.t1 > 0.0 ? roots.t1 : kNoHit;
    if (roots.t0 > 0.0) return roots.t0;
    return roots.t1 > 0.0 ? roots.t1 : kNoHit;
}

}  // namespace rc
