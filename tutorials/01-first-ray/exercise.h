#pragma once
// Tutorial 01: a first ray and the complete search.
#include "geometry/intersection.h"  // rc::kNoHit
#include "scene/scene.h"  // rc::Scene, rc::Ray, rc::RayOrigin

namespace tutorial {

// [declaration]
/// A ray to answer (RayCache's rc::Query, the fields this tutorial needs).
struct Query {
    rc::Ray ray;
    double tmax = rc::kNoHit;  ///< hits at or beyond tmax do not count
    rc::RayOrigin origin;      ///< the surface the ray starts on (object -1: the eye)
};
/// An answer: the object hit first (-1: none) and its distance (rc::kNoHit: none).
struct Answer {
    int object = -1;
    double t = rc::kNoHit;
};

/// The nearest object that the query's ray hits, or no hit (object -1, t = kNoHit).
/// Test every object of the scene with scene.intersect(); only hits with t < q.tmax
/// count; a ray leaving the surface it starts on (q.origin, not inside) cannot hit that
/// object again; equal distances go to the lower object id.
Answer nearestHit(const rc::Scene& scene, const Query& q);
// [declaration]

}  // namespace tutorial
