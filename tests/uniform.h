#pragma once
// Uniform doubles in [lo, hi) drawn from RayCache's one generator, rc::Random: the same
// numbers with every standard library (std::uniform_real_distribution's are not).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/ray.h"
#include "scene/random.h"

struct Uniform {
    double lo, hi;
    double operator()(rc::Random& r) const { return r.uniform(lo, hi); }
};

/// Uniform on the unit sphere (Archimedes: z uniform in [-1, 1], the angle uniform).
inline rc::Vec3 randomUnit(rc::Random& rng) {
    const double z = rng.uniform(-1.0, 1.0), phi = 2.0 * std::numbers::pi * rng.unit();
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return rc::Vec3(s * std::cos(phi), s * std::sin(phi), z);
}
