#include "search/complete_search.h"

#include <glm/common.hpp>

namespace rc {

void CompleteSearch::objectsNear(const Vec3&, const Vec3&, std::vector<int>& out) const {
    out.resize(std::size_t(scene_.size()));
    for (int id = 0; id < scene_.size(); ++id) out[id] = id;
}

void CompleteSearch::objectsNearSegment(const Vec3& a, const Vec3& b, double radius, std::vector<int>& out) const {
    objectsNear(glm::min(a, b) - Vec3(radius), glm::max(a, b) + Vec3(radius), out);
}

Answer LinearSearch::nearest(const Query& q, Counters& n) const {
    // [linear-search]
    // Test every object; keep the nearest hit in front of tmax
    Answer best;
    for (int id = 0; id < scene_.size(); ++id) testObject(scene_, q, id, best, n);
    return best;
    // [linear-search]
}

}  // namespace rc
