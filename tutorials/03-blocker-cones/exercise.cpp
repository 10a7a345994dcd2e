/// \file
/// \brief The convex hull of two spheres (the solid of a blocker cone): rc::Hull, tutorial 03's hole. A student build
/// compiles tutorials/03-blocker-cones/exercise.cpp in place of this file.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/student_code.h"

namespace rc {

Hull::Hull(const Sphere& a, const Sphere& b) : a_(a), b_(b) {
    // TODO 1: what distance() needs, computed once per hull (the members in geometry/cone.h).
    nested_ = false;
}

double Hull::distance(const Vec3& p) const {
    // TODO 2: the hull is both spheres and the cone between them; this sees sphere a only.
    notYet(3);
    return glm::length(p - a_.c) - a_.r;
}

}  // namespace rc
