// Tutorial 07, a partial answer (basic and intermediate pass, the challenge does not): the
// cache keeps only the exact empty cone of the last ray that hit nothing, with no list.
#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>

#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

namespace {
double angleBetween(const rc::Vec3& a, const rc::Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}
}  // namespace

// [solution-basic]
double emptyConeAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres) {
    double angle = rc::kNoHit;
    for (const rc::Sphere& s : spheres) {
        const rc::Vec3 v = s.c - apex;
        const double dist = glm::length(v);
        if (s.r >= dist) return -1.0;  // the apex is inside this sphere: every ray meets it
        // The cone may open until it touches the sphere's disc of directions
        angle = std::min(angle, angleBetween(axis, v) - std::asin(s.r / dist));
    }
    return angle;
}
// [solution-basic]

namespace {

// [solution-cache]
class ConeListCache final : public NothingCache {
public:
    explicit ConeListCache(const Spheres& spheres) : spheres_(spheres) {}

    Known lookup(const rc::Vec3& d) override {
        // The angle between neighbouring pixels, learnt from the rays asked so far
        if (havePrevious_) {
            const double step = angleBetween(previous_, d);
            if (step > 0.0) pitch_ = std::min(pitch_, step);
        }
        previous_ = d;
        havePrevious_ = true;
        // A cone that holds d: only the spheres on its list can be hit
        for (const Cone& cone : cones_) {
            if (glm::dot(d, cone.axis) < cone.cosAngle) continue;
            // A sphere whose disc lies farther from the axis than d does cannot be hit,
            // and needs no test: the angle from d to its centre is at least its gap's
            // worth more than its radius (the triangle inequality on angles)
            const double fromAxis = angleBetween(cone.axis, d);
            rc::Answer best;
            for (const auto& [j, gap] : cone.list) {
                if (fromAxis < gap - kAngleMargin) continue;
                const double t = spheres_.distance(d, j);
                if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
            }
            return {true, best.object};
        }
        return {};
    }

    void searched(const rc::Vec3& d, int object) override {
        if (object >= 0) return;  // this cache is built from rays that hit nothing
        // One look at every sphere: the gap between d and its disc of directions
        gaps_.resize(spheres_.size());
        double empty = rc::kNoHit;
        for (int j = 0; j < spheres_.size(); ++j) {
            const Spheres::Disc disc = spheres_.disc(d, j);
            gaps_[j] = disc.centreAngle - disc.radius;
            empty = std::min(empty, gaps_[j]);
        }
        // Wider than the empty cone by a few pixels: the spheres in the margin go on a list
        const double angle = std::max(empty, kMarginPixels * (std::isinf(pitch_) ? 0.0 : pitch_));
        Cone cone{d, std::cos(std::min(angle, M_PI)), {}};
        if (empty < angle)
            for (int j = 0; j < spheres_.size(); ++j)
                if (gaps_[j] <= angle) cone.list.push_back({j, gaps_[j]});
        // Shrink by a hair so that rounding never admits a ray from outside the cone
        cone.cosAngle += 1e-12;
        cones_.push_front(std::move(cone));
        if (cones_.size() > kCones) cones_.pop_back();
    }

private:
    static constexpr double kMarginPixels = 0.0;  // how far past the empty cone a cone reaches
    static constexpr std::size_t kCones = 1;       // cones kept, the newest first
    static constexpr double kAngleMargin = 1e-9;   // radians, far above the angles' rounding
    struct Cone {
        rc::Vec3 axis;
        double cosAngle;        ///< cos of the half-angle
        std::vector<std::pair<int, double>> list;  ///< spheres that meet the cone, and their gaps from its axis
    };
    const Spheres& spheres_;
    std::vector<double> gaps_;
    std::deque<Cone> cones_;
    rc::Vec3 previous_{0.0};
    bool havePrevious_ = false;
    double pitch_ = rc::kNoHit;
};
// [solution-cache]

}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const Spheres& spheres) {
    return std::make_unique<ConeListCache>(spheres);
}

}  // namespace tutorial
