// The standard ray-tracing algorithm: tutorial 01's hole. A student build compiles
// tutorials/01-first-ray/exercise.cpp in place of this file.
#include "search/standard_algorithm.h"

#include "geometry/student_code.h"

namespace rc {

void standardTest(const Scene& scene, const Query& q, int id, Answer& best, Counters& n) {
    // TODO 1: test object id, and keep it in best if it is the nearest hit so far.
    notYet(1);
    (void)scene, (void)q, (void)id, (void)best, (void)n;
}

Answer standardAlgorithm(const Scene& scene, const Query& q, Counters& n) {
    // TODO 2: test every object of the scene and keep the nearest hit.
    notYet(1);
    (void)scene, (void)q, (void)n;
    return Answer{};  // "hits nothing": right for rays into the background only
}

}  // namespace rc
