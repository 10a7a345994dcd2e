#pragma once
/// \file
/// \brief Light (NFF `l x y z [r g b]`): a point, or a sphere for soft shadows.
#include "geometry/ray.h"

namespace rc {

/// A light: a point (radius 0, as NFF gives it), or a sphere of that radius around
/// `position`, whose shadow rays go to points of the sphere (`--light-radius`).
struct Light {
    Vec3 position{0.0};
    Vec3 color{1.0};
    double radius = 0.0;
};

}  // namespace rc
