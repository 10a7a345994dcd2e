#include "geometry/truncated_cone.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/intersection.h"

namespace rc {

std::optional<std::string> makeTruncatedCone(const Vec3& base, double baseRadius, const Vec3& apex,
                                             double apexRadius, TruncatedCone& out) {
    if (baseRadius < 0.0 || apexRadius < 0.0) return "cone radius must not be negative";
    if (!(baseRadius > 0.0 || apexRadius > 0.0)) return "cone has both radii zero (a line, not a surface)";
    const Vec3 along = apex - base;
    const double big = std::max({std::abs(along.x), std::abs(along.y), std::abs(along.z)});
    const double height = big > 0.0 ? big * glm::length(along / big) : 0.0;
    const double size = std::max({glm::length(base), glm::length(apex), baseRadius, apexRadius});
    if (!(height > 1e-12 * size) || !std::isfinite(height))
        return "cone's base and apex centres coincide";
    out.base = base;
    out.axis = along / height;
    out.baseRadius = baseRadius;
    out.apexRadius = apexRadius;
    out.height = height;
    out.slope = (apexRadius - baseRadius) / height;
    return std::nullopt;
}

namespace {
// The nearest root in front of the origin between the two rims, once the ray's line meets
// the cone's surface. Apart from intersectTruncatedCone() because its roots come from another
// file (tutorial 06's hole): the rays that miss return before this call and pay nothing for it.
[[gnu::noinline]] double nearestBetweenRims(double a, double h, double c, double disc, double s0, double ds,
                                            double height, bool fromThis, double scale) {
    // The roots as the spheres take theirs (tutorial 06). Tangent at the origin's height
    // (both roots 0, or 0 / 0 when a is 0 too), neither counts below
    const QuadraticRoots stable = stableQuadraticRoots(a, h, c, disc);
    double roots[2] = {stable.larger, stable.smaller};
    // A ray starting on the surface: the smaller root is the one at its origin (c is 0
    // there, up to rounding); only the other can be a hit, and only if it lies clear of
    // the origin
    if (fromThis) {
        roots[1] = kNoHit;
        if (!(std::abs(roots[0]) > 1e-9 * scale)) return kNoHit;
    }
    if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    // The nearest root in front of the origin, between the two rims
    for (const double t : roots) {
        if (!(t > 0.0) || !std::isfinite(t)) continue;
        const double s = s0 + t * ds;
        if (s >= 0.0 && s <= height) return t;
    }
    return kNoHit;
}
}  // namespace

double intersectTruncatedCone(const Ray& ray, const TruncatedCone& cone, bool fromThis) {
    // [cone-hit]
    // Split origin offset and direction into parts along the axis and across it
    const Vec3 w = ray.o - cone.base;
    const double s0 = glm::dot(w, cone.axis), ds = glm::dot(ray.d, cone.axis);
    const Vec3 wp = w - s0 * cone.axis, dp = ray.d - ds * cone.axis;
    const double k = cone.slope;
    const double r0 = cone.baseRadius + k * s0;  // the radius at the origin's height
    // |wp + t dp|^2 = (r0 + k ds t)^2, i.e. a t^2 + 2 h t + c = 0
    const double a = glm::dot(dp, dp) - k * k * ds * ds;
    const double h = glm::dot(wp, dp) - k * r0 * ds;
    const double c = glm::dot(wp, wp) - r0 * r0;
    // The discriminant h^2 - a c as a difference of two squared lengths, which keeps its
    // digits on grazing rays: |r0 dp - k ds wp|^2 - |wp x dp|^2
    const Vec3 e = r0 * dp - (k * ds) * wp;
    const Vec3 x = glm::cross(wp, dp);
    const double disc = glm::dot(e, e) - glm::dot(x, x);
    if (disc < 0.0) return kNoHit;
    // The size of the problem at the origin, for a ray that starts on the surface
    const double scale = fromThis ? glm::length(wp) + std::abs(r0) + cone.height : 0.0;
    return nearestBetweenRims(a, h, c, disc, s0, ds, cone.height, fromThis, scale);
    // [cone-hit]
}

Vec3 truncatedConeNormal(const TruncatedCone& cone, const Vec3& p) {
    // The gradient of |across|^2 - r(s)^2: across - k r(s) axis
    const Vec3 w = p - cone.base;
    const double s = glm::dot(w, cone.axis);
    const Vec3 across = w - s * cone.axis;
    const double r = cone.baseRadius + cone.slope * s;
    const Vec3 n = across - (cone.slope * r) * cone.axis;
    const double l = glm::length(n);
    if (l > 0.0) return n / l;
    return cone.slope > 0.0 ? -cone.axis : cone.axis;  // the tip of a cone
}

Sphere boundingSphere(const TruncatedCone& cone) {
    const double half = 0.5 * cone.height;
    const double r = std::max(std::hypot(half, cone.baseRadius), std::hypot(half, cone.apexRadius));
    return {cone.base + half * cone.axis, r * (1.0 + 1e-12)};
}

void boundingBox(const TruncatedCone& cone, Vec3& lo, Vec3& hi) {
    const Vec3 across = glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - cone.axis * cone.axis));
    const Vec3 apex = cone.apex();
    lo = glm::min(cone.base - cone.baseRadius * across, apex - cone.apexRadius * across);
    hi = glm::max(cone.base + cone.baseRadius * across, apex + cone.apexRadius * across);
}

}  // namespace rc
