// Tutorial 02: the exercise as shipped, a READ-ONLY copy of exercise.cpp. Do not edit it:
// your work goes in exercise.cpp. The docs quote this file and CI checks that it still fails.
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
