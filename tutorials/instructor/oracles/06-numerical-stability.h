#pragma once
// Tutorial 06's oracles (the instructor's: the student edition ships their answers as data,
// tutorials/06-numerical-stability/oracle_data.txt, never this code). Included by the
// recording program's oracles.cpp (TUTORIAL_RECORD).
#include <vector>

#include "geometry/intersection.h"
#include "search/query.h"
#include "oracle_roots.h"

namespace tutorial::instructor {

// The roots by bisection and Newton's method (oracle_roots.h): {hit, t0, t1}
inline std::vector<double> roots(const rc::Ray& ray, const rc::Sphere& s) {
    const OracleRoots r = tutorial::oracleRoots(ray, s);
    if (!r.hit) return {0.0, 0.0, 0.0};
    return {1.0, double(r.t0), double(r.t1)};
}

// The nearest root in front over every sphere, ties to the lower index
inline double firstHit(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres) {
    rc::Answer best;
    for (int j = 0; j < int(spheres.size()); ++j) {
        const std::vector<double> r = roots(ray, spheres[j]);
        const double t = r[0] == 0.0 ? rc::kNoHit : r[1] > 0.0 ? r[1] : r[2] > 0.0 ? r[2] : rc::kNoHit;
        if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
    }
    return best.object;
}

}  // namespace tutorial::instructor
