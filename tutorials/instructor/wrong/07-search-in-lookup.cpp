// Tutorial 07, a wrong answer: a complete search under another name. The lookup tests
// every sphere and answers with the nearest: exact, and the check never has to search,
// but every answer costs n tests (the check counts them, and counts each such lookup as
// the complete search it is), so it is no cheaper than no cache at all, on every scene,
// pair's two spheres included.
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

class EverySphere final : public NothingCache {
public:
    explicit EverySphere(const Spheres& spheres) : spheres_(spheres) {}
    Known lookup(const rc::Vec3& d) override {
        rc::Answer best;
        for (int j = 0; j < spheres_.size(); ++j) {
            const double t = spheres_.distance(d, j);
            if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
        }
        return {true, best.object};
    }
    void searched(const rc::Vec3&, int) override {}

private:
    const Spheres& spheres_;
};

}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const Spheres& spheres) {
    return std::make_unique<EverySphere>(spheres);
}

}  // namespace tutorial
