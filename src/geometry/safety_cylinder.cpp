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
    // BEGIN SOLUTION 02
    // [segment-distance]
    const Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    // The nearest point is a + t (b - a), t clamped to the segment (0 when it is a point)
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
    // [segment-distance]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 1: the distance to the nearest point of the segment, not just to its start.
    // notYet(2);
    // (void)b;
    // return glm::length(p - a);
    // END STUB
}

double safetyRadius(const std::vector<Sphere>& spheres, int hit, const Vec3& a, const Vec3& b) {
    // BEGIN SOLUTION 02
    // [safety-radius]
    // The gap to the nearest other sphere is measured from its surface
    double gap = kNoHit;
    for (int j = 0; j < int(spheres.size()); ++j)
        if (j != hit) gap = std::min(gap, segmentDistance(spheres[j].c, a, b) - spheres[j].r);
    return gap;
    // [safety-radius]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 2: the gap between the segment and the nearest other sphere.
    // (void)spheres, (void)hit, (void)a, (void)b;
    // return kNoHit;
    // END STUB
}

bool SafetyCylinder::contains(const Vec3& p, const Vec3& q) const {
    // BEGIN SOLUTION 02
    // [capsule-contains]
    // Convex: when both ends are in, so is every point between them
    return distance(p) <= radius && distance(q) <= radius;
    // [capsule-contains]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 3: is the whole segment p-q inside the capsule?
    // (void)p, (void)q;
    // return false;
    // END STUB
}

}  // namespace rc
