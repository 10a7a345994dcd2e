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
    // BEGIN SOLUTION 03
    // [hull-setup]
    const Vec3 axis = b.c - a.c;
    D_ = glm::length(axis);
    // One sphere inside the other: the hull is the larger sphere
    nested_ = D_ <= std::abs(a.r - b.r);
    if (nested_) {
        if (b.r > a.r) a_ = b;
        return;
    }
    u_ = axis / D_;
    // The tangent line touches A at ra*n and B at (D,0) + rb*n, with n = (s, c)
    s_ = (a.r - b.r) / D_;
    c_ = std::sqrt(std::max(0.0, 1.0 - s_ * s_));
    // [hull-setup]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 1: what distance() needs, computed once per hull (the members in geometry/cone.h).
    // nested_ = false;
    // END STUB
}

double Hull::distance(const Vec3& p) const {
    // BEGIN SOLUTION 03
    // [hull-distance]
    if (nested_) return glm::length(p - a_.c) - a_.r;
    // Work in the half-plane through the axis: x along it, y away from it
    const Vec3 ap = p - a_.c;
    const double x = glm::dot(ap, u_);
    const double y = glm::length(ap - x * u_);
    // Position along the tangent segment decides which piece of the boundary is nearest
    const double along = (x - a_.r * s_) * c_ - (y - a_.r * c_) * s_;
    if (along < 0.0) return std::sqrt(x * x + y * y) - a_.r;
    if (along > D_ * c_) return std::sqrt((x - D_) * (x - D_) + y * y) - b_.r;
    return x * s_ + y * c_ - a_.r;
    // [hull-distance]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 2: the hull is both spheres and the cone between them; this sees sphere a only.
    // notYet(3);
    // return glm::length(p - a_.c) - a_.r;
    // END STUB
}

}  // namespace rc
