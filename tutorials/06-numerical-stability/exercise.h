#pragma once
// Tutorial 06: numerical stability of the ray-sphere intersection.
#include <limits>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {

// [declaration]
/// The two roots of a ray-sphere equation, when `hit`.
struct Roots {
    bool hit = false;
    double t0 = std::numeric_limits<double>::infinity();  ///< the smaller root
    double t1 = std::numeric_limits<double>::infinity();  ///< the larger root
};

/// Both roots t0 <= t1 of |o + t d - c|^2 = r^2 for a unit direction d, or hit = false.
/// Must stay accurate for small spheres far away, where the textbook formula fails.
Roots stableRoots(const rc::Ray& ray, const rc::Sphere& s);
// [declaration]

}  // namespace tutorial
