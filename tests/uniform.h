#pragma once
// Uniform doubles in [lo, hi) drawn from RayCache's one generator, rc::Random: the same
// numbers with every standard library (std::uniform_real_distribution's are not).
#include "scene/random.h"

struct Uniform {
    double lo, hi;
    double operator()(rc::Random& r) const { return r.uniform(lo, hi); }
};
