#pragma once
// Culling questions the tests ask every complete search: the objects within a blocker
// hull, and the object nearest a segment.
#include <algorithm>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/safety_cylinder.h"
#include "search/complete_search.h"

namespace rc::testing {

// Every object within `limit` of a sphere's hull, as a cull finds them
struct HullQuery final : SphereCull {
    Sphere from, to;
    std::vector<int> ids;
    HullQuery(const Sphere& f, const Sphere& t) : from(f), to(t) {
        a = f.c;
        b = t.c;
        radius = std::max(f.r, t.r);
    }
    double distance(const Sphere& s) override { return hullDistance(s.c, from, to) - s.r; }
    void found(int id, double) override { ids.push_back(id); }
};
// The nearest object to a segment: the limit shrinks as objects are found
struct NearestToSegment final : SphereCull {
    int nearest = -1;
    NearestToSegment(const Vec3& p, const Vec3& q) {
        a = p;
        b = q;
        limit = kNoHit;
    }
    double distance(const Sphere& s) override { return segmentDistance(s.c, a, b) - s.r; }
    void found(int id, double d) override {
        if (d < limit || (d == limit && id < nearest)) nearest = id;
        limit = std::min(limit, d);
    }
};
}  // namespace rc::testing
