#include "search/complete_search.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "search/segment_clearance.h"

namespace rc {

void CompleteSearch::cull(SphereCull& c) const {
    for (int id = 0; id < scene_.size(); ++id) {
        const double d = c.distance(scene_.objects[id].bound);
        if (d <= c.limit) c.found(id, d);
    }
}

double CompleteSearch::clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                                 double stopBelow, int* nearest) const {
    SegmentClearance c(a, b, skip, skipToo, cap, stopBelow);
    cull(c);
    if (nearest) *nearest = c.nearest;
    return c.least;
}

}  // namespace rc
