/// \file
/// \brief The measures of the cylinder of safety: rc::segmentDistance, rc::safetyRadius and
/// rc::SafetyCylinder::contains, tutorial 02's hole. A student build compiles
/// tutorials/02-safety-cylinder/exercise.cpp in place of this file.
#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/safety_cylinder.h"
#include "geometry/student_code.h"

namespace rc {

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
    // TODO 1: the distance to the nearest point of the segment, not just to its start.
    notYet(2);
    (void)b;
    return glm::length(p - a);
}

double safetyRadius(const std::vector<Sphere>& spheres, int hit, const Vec3& a, const Vec3& b) {
    // TODO 2: the gap between the segment and the nearest other sphere.
    (void)spheres, (void)hit, (void)a, (void)b;
    return kNoHit;
}

bool SafetyCylinder::contains(const Vec3& p, const Vec3& q) const {
    // TODO 3: is the whole segment p-q inside the capsule?
    (void)p, (void)q;
    return false;
}

}  // namespace rc
