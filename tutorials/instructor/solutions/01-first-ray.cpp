// Tutorial 01, the reference solution.
#include "exercise.h"

namespace tutorial {

// [solution]
Answer nearestHit(const rc::Scene& scene, const Query& q) {
    Answer best;  // object -1, t = kNoHit
    for (int id = 0; id < scene.size(); ++id) {
        // Convexity: a ray leaving a surface cannot meet it again
        if (id == q.origin.object && !q.origin.inside) continue;
        const double t = scene.intersect(q.ray, id, q.origin);
        if (t < q.tmax && (t < best.t || (t == best.t && id < best.object))) best = {id, t};
    }
    return best;
}
// [solution]

}  // namespace tutorial
