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
    // BEGIN SOLUTION 06
    // [stable-quadratic]
    // q has the sign of -h, so -h and the square root never cancel
    const double root = std::sqrt(disc);
    const double q = (h > 0.0) ? -h - root : -h + root;
    // The larger root from q, the smaller from Vieta (t0 t1 = c / a)
    return {q / a, (q != 0.0) ? c / q : 0.0};
    // [stable-quadratic]
    // END SOLUTION
    // BEGIN STUB
    // // TODO: these are the textbook roots (-h -+ sqrt(disc)) / a. One of the two subtracts
    // // nearly equal numbers when a c is small next to h^2: make both keep their digits.
    // notYet(6);
    // (void)c;  // the textbook roots do without it
    // const double w = std::sqrt(disc);
    // const double minus = (-h - w) / a, plus = (-h + w) / a;
    // if (std::abs(minus) >= std::abs(plus)) return {minus, plus};
    // return {plus, minus};
    // END STUB
}

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
    // |f + t d|^2 = r^2 is t^2 + 2 b t + c = 0 for a unit d
    const double c = glm::dot(f, f) - s.r * s.r;
    const QuadraticRoots roots = stableQuadraticRoots(1.0, b, c, disc);
    double t0 = roots.smaller;
    double t1 = roots.larger;
    if (t0 > t1) std::swap(t0, t1);
    return {true, t0, t1};
    // [stable-roots]
    // END SOLUTION
    // BEGIN STUB
    // // TODO: this is the textbook formula. It is right on paper and wrong in doubles when
    // // the sphere is small and far away: b*b and c are huge and nearly equal. Make it
    // // stable (the roots of any quadratic: stableQuadraticRoots() above), and keep t0 <= t1.
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
