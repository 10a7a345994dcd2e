#pragma once
/// \file
/// \brief The directions in which a ray leaving a ball can meet a sphere, measured
/// against a cone of directions without trigonometry.
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/sphere.h"

namespace rc {

/// A ray leaving any point within `reach` of `from` meets sphere `s` only in directions
/// within beta = asin((s.r + reach) / |s.c - from|) of the centre's direction (the ray
/// through `from` parallel to it passes within s.r + reach of s.c). Returns how far unit
/// direction `axis` lies outside those directions, as 1 - cos(theta - beta) with theta the
/// angle from `axis` to the centre: negated when the axis is inside, -inf when `s` reaches
/// `from` (every direction may meet it). It grows with theta - beta, so a cone of
/// half-angle alpha around `axis` meets the directions exactly when it is at most
/// 1 - cos(alpha); and a sphere inside `s` lies at least as far.
inline double directionGap(const Vec3& from, double reach, const Vec3& axis, const Sphere& s) {
    const Vec3 v = s.c - from;
    const double dist = glm::length(v);
    const double sinB = (s.r + reach) / dist;
    if (!(sinB < 1.0)) return -kNoHit;
    const double cosB = std::sqrt(1.0 - sinB * sinB);
    const double sinT = glm::length(glm::cross(axis, v)) / dist, cosT = glm::dot(axis, v) / dist;
    // cos(theta - beta), and the sign of sin(theta - beta)
    const double gap = 1.0 - (cosT * cosB + sinT * sinB);
    return sinT * cosB - cosT * sinB < 0.0 ? -gap : gap;
}

}  // namespace rc
