#pragma once
/// \file
/// \brief NFF surface material: `f r g b Kd Ks Shine T ior`.
#include "geometry/ray.h"

namespace rc {

/// Whitted material, as NFF's `f` line gives it.
struct Material {
    Vec3 color{1.0};     ///< r g b
    double kd = 1.0;     ///< diffuse
    double ks = 0.0;     ///< specular, also the weight of the reflected ray
    double shine = 0.0;  ///< Phong exponent
    double kt = 0.0;     ///< transmission, the weight of the refracted ray
    double ior = 1.0;    ///< index of refraction
};

}  // namespace rc
