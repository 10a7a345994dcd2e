#pragma once
/// \file
/// \brief The paper's "standard ray-tracing algorithm" written as a plain loop: tutorial 01's
/// hole, the test of one object and the loop over them all. A student build
/// (`RAYCACHE_STUDENT`) runs the loop as LinearSearch::nearest() and the test as every
/// search's and cache's rc::testObject(), so the renderer draws with the student's code;
/// the instructor's build keeps the inline test and the batched loop of SphereBatch, which
/// return the same answers and counts.
#include "search/query.h"

namespace rc {

/// One test of the standard algorithm: object `id` of `scene` tested against `q` with
/// Scene::intersect(), and kept in `best` if it is nearer (rc::nearer: equal distances go
/// to the lower id), with one count in `n.intersectionTests`. Only hits with t < q.tmax
/// count; a ray leaving the surface it starts on (q.origin, not inside) cannot hit that
/// object again: it is neither tested nor counted.
void standardTest(const Scene& scene, const Query& q, int id, Answer& best, Counters& n);

/// The nearest object `q`'s ray hits: every object of `scene` tested as standardTest()
/// does, starting from nothing hit (object -1, t = kNoHit).
Answer standardAlgorithm(const Scene& scene, const Query& q, Counters& n);

}  // namespace rc
