// Tutorial 07, a reference solution (one of many: the check grades by measurement). The
// cache keeps a few cones of directions, each built where a ray hit nothing, each wider
// than its empty cone and carrying the short list of spheres that meet it: a "blocker
// list" for a cone of directions. A ray inside a cone tests only that list, so it is
// answered whether it hits nothing or a sphere.
#include <algorithm>
#include <cmath>
#include <deque>

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
    ConeListCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) : spheres_(spheres), eye_(eye) {}

    Known lookup(const rc::Vec3& d, long& tests) override {
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
            const rc::Ray ray{eye_, d};
            rc::Answer best;
            for (int j : cone.list) {
                ++tests;
                const double t = rc::intersectSphere(ray, spheres_[j], rc::Start::Elsewhere);
                if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
            }
            return {true, best.object};
        }
        return {};
    }

    void searched(const rc::Vec3& d, int object) override {
        if (object >= 0) return;  // this cache is built from rays that hit nothing
        // Wider than the empty cone by a few pixels: the spheres in the margin go on a list
        const double empty = emptyConeAngle(eye_, d, spheres_);
        const double angle = std::max(empty, kMarginPixels * (std::isinf(pitch_) ? 0.0 : pitch_));
        Cone cone{d, std::cos(std::min(angle, M_PI)), {}};
        if (empty < angle)
            for (int j = 0; j < int(spheres_.size()); ++j) {
                const rc::Vec3 v = spheres_[j].c - eye_;
                const double dist = glm::length(v);
                if (spheres_[j].r >= dist || angleBetween(d, v) - std::asin(spheres_[j].r / dist) <= angle)
                    cone.list.push_back(j);
            }
        // Shrink by a hair so that rounding never admits a ray from outside the cone
        cone.cosAngle += 1e-12;
        cones_.push_front(std::move(cone));
        if (cones_.size() > kCones) cones_.pop_back();
    }

private:
    static constexpr double kMarginPixels = 8.0;  // how far past the empty cone a cone reaches
    static constexpr std::size_t kCones = 16;      // cones kept, the newest first
    struct Cone {
        rc::Vec3 axis;
        double cosAngle;        ///< cos of the half-angle
        std::vector<int> list;  ///< spheres that meet the cone
    };
    std::vector<rc::Sphere> spheres_;
    rc::Vec3 eye_;
    std::deque<Cone> cones_;
    rc::Vec3 previous_{0.0};
    bool havePrevious_ = false;
    double pitch_ = rc::kNoHit;
};
// [solution-cache]

}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) {
    return std::make_unique<ConeListCache>(spheres, eye);
}

}  // namespace tutorial
