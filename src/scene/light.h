#pragma once
/// \file
/// \brief Point light (NFF `l x y z [r g b]`).
#include "geometry/ray.h"

namespace rc {

/// A point light.
struct Light {
    Vec3 position{0.0};
    Vec3 color{1.0};
};

}  // namespace rc
