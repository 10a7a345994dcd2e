#pragma once
/// \file
/// \brief The NFF view (`v` block) and how it turns pixels into eye rays.
#include <optional>

#include <glm/vec2.hpp>

#include "geometry/ray.h"

namespace rc {

/// NFF viewing parameters. Follows Eric Haines' SPD convention: `angle` is the full
/// field of view in degrees; right = normalize(cross(at - from, up)); rays go through
/// pixel corners, so column 0 and column W-1 sit at the two edges of the view; row 0
/// is the top.
struct Camera {
    Vec3 from{0.0, 0.0, 5.0};
    Vec3 at{0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double angle = 45.0;
    double hither = 1e-3;
    int width = 512;
    int height = 512;
};

/// Turns pixel coordinates into eye rays for one image size.
class RayGenerator {
public:
    RayGenerator(const Camera& cam, int width, int height);
    /// The eye ray through (fractional) pixel position `x`, `y`.
    Ray primary(double x, double y) const;
    /// The inverse of primary(): the fractional pixel position `(x, y)` whose eye ray
    /// passes through world point `p`, or nothing when `p` is not in front of the eye.
    std::optional<glm::dvec2> project(const Vec3& p) const;

private:
    Vec3 from_, forward_, right_, up_;
    double sx_ = 1.0, sy_ = 1.0;
    int width_ = 1, height_ = 1;
};

}  // namespace rc
