#pragma once
// Seeded random cases for the tutorial checks, drawn from RayCache's one generator
// (rc::Random) and its one pow (rc::pm, musl's), so every machine draws the same cases, bit
// for bit: the checks find their expected values by the bits of a case's inputs
// (oracle_data.h).
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "geometry/portable_math.h"
#include "geometry/ray.h"
#include "scene/random.h"

namespace tutorial {

class Random : public rc::Random {
public:
    using rc::Random::Random;
    /// 10^uniform(lo, hi): scales over orders of magnitude.
    double logUniform(double lo, double hi) { return rc::pm::pow(10.0, uniform(lo, hi)); }
    bool chance(double p) { return unit() < p; }
    rc::Vec3 inBox(double h) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }
    /// A uniformly distributed unit vector.
    rc::Vec3 direction() {
        for (;;) {
            const rc::Vec3 v = inBox(1.0);
            const double l = glm::length(v);
            if (l > 1e-3 && l <= 1.0) return v / l;
        }
    }
};

}  // namespace tutorial
