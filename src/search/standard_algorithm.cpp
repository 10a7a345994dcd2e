// The standard ray-tracing algorithm: tutorial 01's hole. A student build compiles
// tutorials/01-first-ray/exercise.cpp in place of this file.
#include "search/standard_algorithm.h"

#include "geometry/student_code.h"

namespace rc {

void standardTest(const Scene& scene, const Query& q, int id, Answer& best, Counters& n) {
    // BEGIN SOLUTION 01
    // Convexity: a ray leaving a surface cannot meet that surface again
    if (id == q.origin.object && !q.origin.inside) return;
    ++n.intersectionTests;
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && (t < best.t || (t == best.t && id < best.object))) best = {id, t};
    // END SOLUTION
    // BEGIN STUB
    // // TODO 1: test object id, and keep it in best if it is the nearest hit so far.
    // notYet(1);
    // (void)scene, (void)q, (void)id, (void)best, (void)n;
    // END STUB
}

Answer standardAlgorithm(const Scene& scene, const Query& q, Counters& n) {
    // BEGIN SOLUTION 01
    Answer best;  // object -1, t = kNoHit
    for (int id = 0; id < scene.size(); ++id) standardTest(scene, q, id, best, n);
    return best;
    // END SOLUTION
    // BEGIN STUB
    // // TODO 2: test every object of the scene and keep the nearest hit.
    // notYet(1);
    // (void)scene, (void)q, (void)n;
    // return Answer{};  // "hits nothing": right for rays into the background only
    // END STUB
}

}  // namespace rc
