// Tutorial 02, your exercise: distance from a point to a segment. This file is yours to edit. Check it with
//   cmake --build build --target tutorial-02      (or: ctest --preset student -R 02)
#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

// [stub]
double segmentDistance(const rc::Vec3& p, const rc::Vec3& a, [[maybe_unused]] const rc::Vec3& b) {
    // TODO 1: the distance to the nearest point of the segment, not just to its start.
    return glm::length(p - a);
}

double safetyRadius([[maybe_unused]] const std::vector<rc::Sphere>& spheres, [[maybe_unused]] int hit,
                    [[maybe_unused]] const rc::Vec3& a, [[maybe_unused]] const rc::Vec3& b) {
    // TODO 2: the gap between the segment and the nearest other sphere.
    return rc::kNoHit;
}

bool insideCapsule([[maybe_unused]] const rc::Vec3& p, [[maybe_unused]] const rc::Vec3& q,
                   [[maybe_unused]] const rc::Vec3& a, [[maybe_unused]] const rc::Vec3& b,
                   [[maybe_unused]] double radius) {
    // TODO 3: is the whole segment p-q inside the capsule?
    return false;
}
// [stub]

}  // namespace tutorial
