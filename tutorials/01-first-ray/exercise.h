#pragma once
// Tutorial 01: a first ray and the complete search.
#include "search/query.h"

namespace tutorial {

// [declaration]
/// The nearest object that the query's ray hits, or no hit (object -1, t = kNoHit).
/// Test every object of the scene with scene.intersect(); only hits with t < q.tmax
/// count; a ray leaving the surface it starts on (q.origin, not inside) cannot hit that
/// object again; equal distances go to the lower object id (rc::nearer).
rc::Answer nearestHit(const rc::Scene& scene, const rc::Query& q);
// [declaration]

}  // namespace tutorial
