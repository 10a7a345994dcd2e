#pragma once
/// \file
/// \brief NFF `c`: an open truncated cone between two disc centres (equal radii: a cylinder).
#include <optional>
#include <string>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace rc {

/// The lateral surface of a truncated cone, open at both ends: the points whose distance
/// from the axis is `r(s) = baseRadius + slope * s` at height `s` in [0, height] above
/// the base disc's centre. Rays that leave it may meet it again (it is not convex).
struct TruncatedCone {
    Vec3 base{0.0};            ///< centre of the base disc
    Vec3 axis{0.0, 0.0, 1.0};  ///< unit axis from the base towards the apex disc
    double baseRadius = 1.0;   ///< rb
    double apexRadius = 1.0;   ///< ra
    double height = 1.0;       ///< H = |apex - base|
    double slope = 0.0;        ///< k = (ra - rb) / H
    Vec3 apex() const { return base + height * axis; }
};

/// Builds the cone `c bx by bz br ax ay az ar`. Returns an explanation instead when a
/// radius is negative, both are zero, or the two centres coincide.
std::optional<std::string> makeTruncatedCone(const Vec3& base, double baseRadius, const Vec3& apex,
                                             double apexRadius, TruncatedCone& out);

/// Hit distance of a ray with the cone's surface, or kNoHit. `fromThis`: the ray starts
/// on this very surface, so the root at its origin is not a hit (the other one may be).
double intersectTruncatedCone(const Ray& ray, const TruncatedCone& cone, bool fromThis);

/// Outward unit normal (away from the axis) at surface point `p`.
Vec3 truncatedConeNormal(const TruncatedCone& cone, const Vec3& p);

/// A sphere around the two rims: centred halfway along the axis.
Sphere boundingSphere(const TruncatedCone& cone);

/// The cone's axis-aligned box: each rim is a disc whose extent along axis i is r sqrt(1 - u_i^2).
void boundingBox(const TruncatedCone& cone, Vec3& lo, Vec3& hi);

}  // namespace rc
