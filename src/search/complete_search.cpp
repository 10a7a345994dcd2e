#include "search/complete_search.h"


namespace rc {

void CompleteSearch::cull(SphereCull& c) const {
    for (int id = 0; id < scene_.size(); ++id) {
        const double d = c.distance(scene_.objects[id].bound);
        if (d <= c.limit) c.found(id, d);
    }
}

LinearSearch::LinearSearch(const Scene& scene) : CompleteSearch(scene) {
    for (int id = 0; id < scene.size(); ++id) all_.add(scene, id);
}

Answer LinearSearch::nearest(const Query& q, Counters& n) const {
    // [linear-search]
    // Test every object; keep the nearest hit in front of tmax
    Answer best;
    all_.test(scene_, q, 0, all_.size(), best, n);
    return best;
    // [linear-search]
}

}  // namespace rc
