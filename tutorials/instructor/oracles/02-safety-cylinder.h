#pragma once
// Tutorial 02's oracles (the instructor's: the student edition ships their answers as data,
// tutorials/02-safety-cylinder/oracle_data.txt, never this code). Included by the
// recording program's oracles.cpp (TUTORIAL_RECORD).
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "oracle_minimum.h"

namespace tutorial::instructor {

// The distance from p to the segment a-b: the least of |p - (a + u (b - a))| over u in
// [0, 1], a convex function of u, by golden-section search in long double
inline double segmentGap(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b) {
    auto f = [&](long double u) {
        long double d2 = 0.0L;
        for (int i = 0; i < 3; ++i) {
            const long double x = (long double)p[i] - ((long double)a[i] + u * ((long double)b[i] - (long double)a[i]));
            d2 += x * x;
        }
        return std::sqrt(d2);
    };
    return double(minimumOnUnit(f));
}

// Is every one of 17 points spread along p-q within `radius` of the segment a-b?
inline bool capsuleContains(const rc::Vec3& a, const rc::Vec3& b, double radius, const rc::Vec3& p, const rc::Vec3& q) {
    for (int k = 0; k <= 16; ++k)
        if (segmentGap(p + (q - p) * (k / 16.0), a, b) > radius) return false;
    return true;
}

// The gap from the segment a-b to the nearest sphere but `hit`
inline double sphereGap(const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a, const rc::Vec3& b) {
    double r = INFINITY;
    int j = 0;
    for (const rc::Sphere& s : spheres)
        if (j++ != hit) r = std::min(r, segmentGap(s.c, a, b) - s.r);
    return r;
}

}  // namespace tutorial::instructor
