#pragma once
/// \file
/// \brief A sphere: centre and radius. A point is a sphere of radius 0.
#include "geometry/ray.h"

namespace rc {

/// A sphere with centre `c` and radius `r`. Blocker hulls treat a point (the eye, a
/// light) as a sphere of radius 0.
struct Sphere {
    Vec3 c{0.0};
    double r = 0.0;
};

}  // namespace rc
