#pragma once
/// \file
/// \brief The paper's "standard ray-tracing algorithm" written as a plain loop: tutorial 01's
/// hole. A student build (`RAYCACHE_STUDENT`) runs it as LinearSearch::nearest(), so the
/// renderer draws with the student's loop; the instructor's build keeps the batched loop of
/// SphereBatch, which returns the same answers and counts.
#include "search/query.h"

namespace rc {

/// The nearest object `q`'s ray hits: every object of `scene` tested with
/// Scene::intersect(), one count in `n.intersectionTests` per object tested. Only hits
/// with t < q.tmax count; a ray leaving the surface it starts on (q.origin, not inside)
/// cannot hit that object again and is not tested; equal distances go to the lower id.
Answer standardAlgorithm(const Scene& scene, const Query& q, Counters& n);

}  // namespace rc
