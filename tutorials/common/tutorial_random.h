#pragma once
// Seeded random cases for the tutorial checks. Doubles are made by hand from
// std::mt19937_64, so every machine draws the same cases.
#include <cmath>
#include <cstdint>
#include <random>

#include <glm/geometric.hpp>

#include "geometry/ray.h"

namespace tutorial {

class Random {
public:
    explicit Random(std::uint64_t seed) : g_(seed) {}
    /// Uniform in [0, 1).
    double unit() { return double(g_() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// 10^uniform(lo, hi): scales over orders of magnitude.
    double logUniform(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
    int index(int n) { return int(g_() % std::uint64_t(n)); }
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

private:
    std::mt19937_64 g_;
};

}  // namespace tutorial
