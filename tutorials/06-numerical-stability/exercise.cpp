/// \file
/// \brief The stable roots of a quadratic, rc::stableQuadraticRoots(), and of a ray with a sphere,
/// rc::sphereRootsStable(): tutorial 06's hole. A student build compiles
/// tutorials/06-numerical-stability/exercise.cpp in place of this file, so the spheres and the truncated
/// cones (which take their roots from rc::stableQuadraticRoots()) of that build use the student's roots.
/// rc::intersectSphere() is here too, outside the hole: the roots inline into it, as they did before
/// they were a hole (every complete search and cache probe makes one call per sphere).
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/student_code.h"

namespace rc {

QuadraticRoots stableQuadraticRoots(double a, double h, double c, double disc) {
    // TODO: these are the textbook roots (-h -+ sqrt(disc)) / a. One of the two subtracts
    // nearly equal numbers when a c is small next to h^2: make both keep their digits.
    notYet(6);
    (void)c;  // the textbook roots do without it
    const double w = std::sqrt(disc);
    const double minus = (-h - w) / a, plus = (-h + w) / a;
    if (std::abs(minus) >= std::abs(plus)) return {minus, plus};
    return {plus, minus};
}

SphereRoots sphereRootsStable(const Ray& ray, const Sphere& s) {
    // TODO: this is the textbook formula. It is right on paper and wrong in doubles when
    // the sphere is small and far away: b*b and c are huge and nearly equal. Make it
    // stable (the roots of any quadratic: stableQuadraticRoots() above), and keep t0 <= t1.
    notYet(6);
    return sphereRootsTextbook(ray, s);
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
