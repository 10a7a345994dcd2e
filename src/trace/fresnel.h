#pragma once
/// \file
/// \brief How much a dielectric reflects: Fresnel's equations for unpolarized light.
#include <algorithm>
#include <cmath>

namespace rc {

/// The fraction of unpolarized light that a smooth dielectric boundary reflects, for a ray
/// arriving at `cosIncidence` (the cosine between the ray and the normal on its side, in
/// [0, 1]) going from a medium of index `etaFrom` into one of index `etaTo`. Beyond the
/// critical angle the boundary reflects everything (total internal reflection): 1.
///
/// With `sin t = (etaFrom / etaTo) sin i` (Snell), the two polarizations reflect
/// `r_s = (n1 cos i - n2 cos t) / (n1 cos i + n2 cos t)` and
/// `r_p = (n2 cos i - n1 cos t) / (n2 cos i + n1 cos t)`, and the fraction is their mean
/// square (pbrt-v4, section 9.3).
inline double fresnelDielectric(double cosIncidence, double etaFrom, double etaTo) {
    const double cosI = std::clamp(cosIncidence, 0.0, 1.0);
    const double sinI2 = std::max(0.0, 1.0 - cosI * cosI);
    const double ratio = etaFrom / etaTo;
    const double sinT2 = ratio * ratio * sinI2;
    if (sinT2 >= 1.0) return 1.0;  // total internal reflection
    const double cosT = std::sqrt(1.0 - sinT2);
    const double rs = (etaFrom * cosI - etaTo * cosT) / (etaFrom * cosI + etaTo * cosT);
    const double rp = (etaTo * cosI - etaFrom * cosT) / (etaTo * cosI + etaFrom * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

}  // namespace rc
