#pragma once
/// \file
/// \brief A question about the objects' bounding spheres that every complete search answers.
#include "geometry/intersection.h"
#include "geometry/sphere.h"

namespace rc {

/// A question about the objects' bounding spheres that every complete search can answer:
/// which objects meet a region (a blocker hull, a capsule, a cone of directions)? The
/// question measures how far a sphere lies from the region, and an object meets it when
/// its bounding sphere lies within `limit`. The measure must be a lower bound for every
/// sphere inside the one measured, so a hierarchy may skip everything under a bounding
/// sphere beyond the limit, and open the nearest first. The limit may shrink as objects
/// are found (a cylinder of safety narrows with each one).
class SphereCull {
public:
    virtual ~SphereCull() = default;
    /// How far sphere `s`, or any sphere inside it, lies from the region (at least).
    virtual double distance(const Sphere& s) = 0;
    /// Object `id`, whose bounding sphere lies at `distance` <= limit. May lower the limit.
    virtual void found(int id, double distance) = 0;
    double limit = 0.0;
    /// A hint for searches that cannot descend by spheres (a grid): every object that meets
    /// lies within `radius` of the segment a-b (infinite: anywhere).
    Vec3 a{0.0}, b{0.0};
    double radius = kNoHit;
};

}  // namespace rc
