#pragma once
// Tutorial 03's oracles (the instructor's: the student edition ships their answers as data,
// tutorials/03-blocker-cones/oracle_data.txt, never this code). Included by the recording
// program's oracles.cpp (TUTORIAL_RECORD).
#include <cmath>
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "oracle_minimum.h"

namespace tutorial::instructor {

// min over u in [0, 1] of |p - c(u)| - r(u): the convex hull of two spheres is the union
// of the spheres between them, centre and radius moving linearly from a to b; outside
// it, the distance is the least over that family, by golden-section search in long double
// (the function is convex)
inline long double hullGap(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b) {
    auto f = [&](long double u) {
        long double d2 = 0.0L;
        for (int i = 0; i < 3; ++i) {
            const long double c = (long double)a.c[i] + u * ((long double)b.c[i] - (long double)a.c[i]);
            d2 += ((long double)p[i] - c) * ((long double)p[i] - c);
        }
        return std::sqrt(d2) - ((long double)a.r + u * ((long double)b.r - (long double)a.r));
    };
    return minimumOnUnit(f);
}

// The slice of the hull in z = 0 (tutorial::hullSlice), 52 pixels to a number
inline std::vector<double> hullSlice(const rc::Sphere& a, const rc::Sphere& b, int w, int h, double x0, double y0,
                                     double scale) {
    std::vector<double> words((std::size_t(w) * h + 51) / 52, 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            const rc::Vec3 p{x0 + (x + 0.5) * scale, y0 - (y + 0.5) * scale, 0.0};
            if (hullGap(p, a, b) <= 0.0L) words[i / 52] += std::ldexp(1.0, int(i % 52));
        }
    return words;
}

// The ids of the spheres that meet the hull by more than rounding, `skip` left out
inline std::vector<double> blockerList(const rc::Sphere& a, const rc::Sphere& b, const std::vector<rc::Sphere>& spheres,
                                       int skip) {
    std::vector<double> ids;
    for (int id = 0; id < int(spheres.size()); ++id)
        if (id != skip && hullGap(spheres[id].c, a, b) <= spheres[id].r - 1e-9) ids.push_back(id);
    return ids;
}

}  // namespace tutorial::instructor
