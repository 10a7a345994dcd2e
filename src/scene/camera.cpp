#include "scene/camera.h"
#include "geometry/portable_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace rc {

RayGenerator::RayGenerator(const Camera& cam, int width, int height)
    : from_(cam.from), width_(width), height_(height) {
    forward_ = glm::normalize(cam.at - cam.from);
    right_ = glm::normalize(glm::cross(forward_, cam.up));
    up_ = glm::cross(right_, forward_);
    const double half = pm::tan(cam.angle * std::numbers::pi / 360.0);
    const double m = double(std::max(width, height));
    sx_ = half * width / m;
    sy_ = half * height / m;
}

Ray RayGenerator::primary(double x, double y) const {
    // [primary-ray]
    // Pixel corners: column 0 at the left edge of the view, column W-1 at the right
    const double u = width_ > 1 ? 2.0 * x / (width_ - 1) - 1.0 : 0.0;
    const double v = height_ > 1 ? 1.0 - 2.0 * y / (height_ - 1) : 0.0;
    return {from_, glm::normalize(forward_ + u * sx_ * right_ + v * sy_ * up_)};
    // [primary-ray]
}

std::optional<glm::dvec2> RayGenerator::project(const Vec3& p) const {
    const Vec3 w = p - from_;
    const double z = glm::dot(w, forward_);
    if (!(z > 0.0)) return std::nullopt;
    const double u = glm::dot(w, right_) / (z * sx_);
    const double v = glm::dot(w, up_) / (z * sy_);
    return glm::dvec2(width_ > 1 ? (u + 1.0) * 0.5 * (width_ - 1) : 0.0,
                      height_ > 1 ? (1.0 - v) * 0.5 * (height_ - 1) : 0.0);
}

}  // namespace rc
