#include "search/complete_search.h"

#include "search/bounding_volume_hierarchy.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>


namespace rc {

void CompleteSearch::cull(SphereCull& c) const {
    for (int id = 0; id < scene_.size(); ++id) {
        const double d = c.distance(scene_.objects[id].bound);
        if (d <= c.limit) c.found(id, d);
    }
}

double CompleteSearch::clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap) const {
    // How near the segment a sphere inside s can come (the segment worked out once)
    struct Clearance final : SphereCull {
        Clearance(const Vec3& from, const Vec3& to, int skip, int skipToo, double cap)
            : ab(to - from), skip(skip), skipToo(skipToo) {
            a = from;
            b = to;
            const double len2 = glm::dot(ab, ab);
            invLen2 = len2 > 0.0 ? 1.0 / len2 : 0.0;
            radius = limit = cap;
        }
        double distance(const Sphere& s) override {
            const Vec3 p = s.c - a;
            const double t = std::clamp(glm::dot(p, ab) * invLen2, 0.0, 1.0);
            return glm::length(p - t * ab) - s.r;
        }
        void found(int id, double d) override {
            if (id != skip && id != skipToo) limit = std::min(limit, d);
        }
        Vec3 ab;
        double invLen2;
        int skip, skipToo;
    };
    Clearance c(a, b, skip, skipToo, cap);
    cull(c);
    return c.limit;
}

void LinearSearch::cull(SphereCull& c) const {
    if (regions_) {
        regions_->cull(c);
    } else {
        CompleteSearch::cull(c);
    }
}

LinearSearch::LinearSearch(const Scene& scene, Regions regions) : CompleteSearch(scene) {
    for (int id = 0; id < scene.size(); ++id) all_.add(scene, id);
    if (regions == Regions::Hierarchy) regions_ = std::make_unique<const BoundingVolumeHierarchy>(scene);
}

LinearSearch::~LinearSearch() = default;

Answer LinearSearch::nearest(const Query& q, Counters& n) const {
    // [linear-search]
    // Test every object; keep the nearest hit in front of tmax
    Answer best;
    all_.test(scene_, q, 0, all_.size(), best, n);
    return best;
    // [linear-search]
}

}  // namespace rc
