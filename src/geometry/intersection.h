#pragma once
/// \file
/// \brief Ray-sphere intersection: the numerically stable form and the textbook form.
///
/// Both return the two roots of `|o + t d - c|^2 = r^2` for a unit direction `d`.
/// The stable form (Ray Tracing Gems ch. 7, pbrt-v4 §6.8) computes the discriminant
/// from the perpendicular offset of the centre, `r^2 - |f - (f.d) d|^2`, instead of
/// the difference of two large squares, and never subtracts nearly equal numbers
/// when forming the roots.
#include <limits>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace rc {

/// No hit: positive infinity (not the largest finite double), so every distance compares
/// below it and `t < kNoHit` means "hit".
inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

/// The two roots `t0 <= t1` of a ray-sphere equation, when `hit`.
struct SphereRoots {
    bool hit = false;
    double t0 = kNoHit;
    double t1 = kNoHit;
};

/// Stable roots (see file comment). `ray.d` must be a unit vector.
SphereRoots sphereRootsStable(const Ray& ray, const Sphere& s);

/// The two roots of `a t^2 + 2 h t + c = 0`, not sorted: `larger` is the one of larger
/// magnitude, `smaller` the other (the one that is 0 when `c` is). Part of tutorial 06's hole.
struct QuadraticRoots {
    double larger = kNoHit;
    double smaller = kNoHit;
};

/// The roots of `a t^2 + 2 h t + c = 0` (`a` != 0), given its discriminant `disc = h^2 - a c`,
/// which must be >= 0: the caller forms it, each surface in the way that keeps its digits.
/// sphereRootsStable() and the truncated cone (rc::intersectTruncatedCone()) take their roots
/// from here. When `larger` is 0, `smaller` is 0 too.
QuadraticRoots stableQuadraticRoots(double a, double h, double c, double disc);

/// Textbook roots `-b +- sqrt(b^2 - c)`: kept for teaching and for the stability
/// comparison; it loses every digit when the sphere is small and far away.
SphereRoots sphereRootsTextbook(const Ray& ray, const Sphere& s);

/// Where a ray starts relative to the surface it is tested against.
enum class Start {
    Elsewhere,  ///< not on this surface: the nearest root in (0, inf) counts
    Leaving,    ///< on this surface, heading outward: convexity says no hit at all
    Entering,   ///< on this surface, heading inward: only the far root counts
};

/// Nearest hit distance of `ray` with sphere `s`, or kNoHit. No epsilon: a ray that
/// starts on the sphere is told so by `start`, and convexity gives the exact answer.
double intersectSphere(const Ray& ray, const Sphere& s, Start start);

}  // namespace rc
