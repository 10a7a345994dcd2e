/// \file
/// \brief The stable ray-sphere roots, rc::sphereRootsStable(): tutorial 06's hole. A student build
/// compiles tutorials/06-numerical-stability/exercise.cpp in place of this file. rc::intersectSphere()
/// is here too, outside the hole: the roots inline into it, as they did before they were a hole (every
/// complete search and cache probe makes one call per sphere).
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/student_code.h"

namespace rc {

SphereRoots sphereRootsStable(const Ray& ray, const Sphere& s) {
    // BEGIN SOLUTION 06
    // [stable-roots]
    // Offset of the origin from the centre, and its projection on the ray
    const Vec3 f = ray.o - s.c;
    const double b = glm::dot(f, ray.d);
    // The discriminant from the perpendicular offset, not from b*b - c
    const Vec3 l = f - b * ray.d;
    const double disc = s.r * s.r - glm::dot(l, l);
    if (disc < 0.0) return {};
    // q has the sign of -b, so -b and the square root never cancel
    const double root = std::sqrt(disc);
    const double q = (b > 0.0) ? -b - root : -b + root;
    const double c = glm::dot(f, f) - s.r * s.r;
    double t0 = (q != 0.0) ? c / q : 0.0;
    double t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    return {true, t0, t1};
    // [stable-roots]
    // END SOLUTION
    // BEGIN STUB
    // // TODO: this is the textbook formula. It is right on paper and wrong in doubles when
    // // the sphere is small and far away: b*b and c are huge and nearly equal. Make it
    // // stable, and keep t0 <= t1.
    // notYet(6);
    // return sphereRootsTextbook(ray, s);
    // END STUB
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
