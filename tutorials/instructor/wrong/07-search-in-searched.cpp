// Tutorial 07, a wrong answer: the work moved into searched(). After each complete
// search, the cache guesses the directions of the next pixels of the row (steps of the
// last pixel's step) and builds, for each, a cone one pixel wide with the exact list of
// the spheres whose discs meet it: one test of every sphere per pixel ahead. Its lookups
// are nearly free and its answers exact, but it makes a complete search, under another
// name, for nearly every ray: the check counts the tests of searched() too.
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

class RowAhead final : public NothingCache {
public:
    explicit RowAhead(const Spheres& spheres) : spheres_(spheres) {}

    Known lookup(const rc::Vec3& d) override {
        if (havePrevious_) step_ = d - previous_;
        previous_ = d;
        havePrevious_ = true;
        for (const Cone& cone : cones_) {
            if (glm::dot(d, cone.axis) < cone.cosAngle) continue;
            rc::Answer best;
            for (int j : cone.list) {
                const double t = spheres_.distance(d, j);
                if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
            }
            return {true, best.object};
        }
        return {};
    }

    void searched(const rc::Vec3& d, int) override {
        cones_.clear();
        const double width = glm::length(step_);
        if (!(width > 0.0)) return;
        for (int k = 1; k <= kAhead; ++k) {
            // The k-th pixel ahead, guessed; the cone around it reaches a pixel further
            const rc::Vec3 axis = glm::normalize(d + double(k) * step_);
            const double angle = 1.5 * width;
            Cone cone{axis, std::cos(angle) + 1e-12, {}};
            for (int j = 0; j < spheres_.size(); ++j) {
                const Spheres::Disc disc = spheres_.disc(axis, j);
                if (disc.centreAngle - disc.radius <= angle) cone.list.push_back(j);
            }
            cones_.push_back(std::move(cone));
        }
    }

private:
    static constexpr int kAhead = 96;  // a whole row ahead
    struct Cone {
        rc::Vec3 axis;
        double cosAngle;
        std::vector<int> list;
    };
    const Spheres& spheres_;
    std::vector<Cone> cones_;
    rc::Vec3 previous_{0.0}, step_{0.0};
    bool havePrevious_ = false;
};

}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const Spheres& spheres) {
    return std::make_unique<RowAhead>(spheres);
}

}  // namespace tutorial
