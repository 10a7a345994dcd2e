/// \file
/// \brief The stable ray-sphere roots, rc::sphereRootsStable(): tutorial 06's hole. A student build
/// compiles tutorials/06-numerical-stability/exercise.cpp in place of this file.
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/student_code.h"

namespace rc {

SphereRoots sphereRootsStable(const Ray& ray, const Sphere& s) {
    // TODO: this is the textbook formula. It is right on paper and wrong in doubles when
    // the sphere is small and far away: b*b and c are huge and nearly equal. Make it
    // stable, and keep t0 <= t1.
    notYet(6);
    return sphereRootsTextbook(ray, s);
}

}  // namespace rc
