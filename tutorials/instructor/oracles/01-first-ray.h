#pragma once
// Tutorial 01's oracle (the instructor's: the student edition ships its answers as data,
// tutorials/01-first-ray/oracle_data.txt, never this code). Included by the recording
// program's oracles.cpp (TUTORIAL_RECORD).
#include <cmath>
#include <vector>

#include "geometry/intersection.h"
#include "search/query.h"
#include "oracle_roots.h"

namespace tutorial::instructor {

// {object, t, ambiguous, tests}: every sphere's roots by bisection (oracle_roots.h), the
// nearest in front taken (tutorial::oracleNearest says the rules); tests: one per sphere, the
// one the ray leaves excepted
inline std::vector<double> nearest(const std::vector<rc::Sphere>& spheres, const rc::Query& q) {
    long double best = INFINITY;
    int object = -1;
    bool ambiguous = false;
    double tests = 0.0;
    for (int id = int(spheres.size()) - 1; id >= 0; --id) {  // downwards: a tie goes to the lower id
        const bool leaving = id == q.origin.object && !q.origin.inside;
        if (leaving) continue;
        ++tests;
        const OracleRoots r = oracleRoots(q.ray, spheres[id]);
        if (!r.hit) continue;
        const long double t = id == q.origin.object ? r.t1 : r.t0 > 0 ? r.t0 : r.t1;
        if (id != q.origin.object)
            for (long double root : {r.t0, r.t1})
                if (std::abs(root) < 1e-9L || std::abs(root - (long double)q.tmax) < 1e-9L * q.tmax) ambiguous = true;
        if (t > 0 && t < (long double)q.tmax && t <= best) best = t, object = id;
    }
    return {double(object), object < 0 ? rc::kNoHit : double(best), ambiguous ? 1.0 : 0.0, tests};
}

}  // namespace tutorial::instructor
