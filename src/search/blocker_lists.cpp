#include "search/blocker_lists.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/cone.h"

namespace rc {

namespace {
/// The objects that meet the hull of two spheres (a point is a sphere of radius 0).
struct HullCull final : SphereCull {
    HullCull(const Sphere& from, const Sphere& to, double slack, Counters& n, std::vector<std::pair<double, int>>& out)
        : from(from), to(to), slack(slack), n(n), out(out) {
        // The hull lies within the larger radius of the segment between the centres
        a = from.c;
        b = to.c;
        radius = std::max(from.r, to.r) + slack;
        limit = slack;
        out.clear();
    }
    // The hull's distance function is 1-Lipschitz: a lower bound for any sphere inside s
    double distance(const Sphere& s) override {
        ++n.hullTests;
        return hullDistance(s.c, from, to) - s.r;
    }
    void found(int id, double) override { out.emplace_back(0.0, id); }
    Sphere from, to;
    double slack;
    Counters& n;
    std::vector<std::pair<double, int>>& out;
};
}  // namespace

BlockerLists::BlockerLists(const Scene& scene, const CompleteSearch& search)
    : scene_(scene), search_(search), sites_(scene.size() + 1 + int(scene.lights.size())) {
    // Rounding only ever adds spheres to a list: widen the hull by a few ulps of the scene
    slack_ = 1e-9 * scene.extent();
}

Sphere BlockerLists::siteSphere(int site) const {
    if (site < scene_.size()) return scene_.objects[site].bound;
    if (site == eyeSite()) return {scene_.camera.from, 0.0};
    return {scene_.lights[site - scene_.size() - 1].position, 0.0};
}

const std::vector<int>* BlockerLists::find(int origin, int target) const {
    auto it = lists_.find(key(origin, target));
    return it == lists_.end() ? nullptr : &it->second.ids;
}

const BlockerList& BlockerLists::get(int origin, int target, Counters& n) {
    auto [it, fresh] = lists_.try_emplace(key(origin, target));
    if (!fresh) return it->second;
    // [build-blocker-list]
    // Every object whose bounding sphere meets the hull of origin and target may block
    const Sphere a = siteSphere(origin);
    const Sphere b = siteSphere(target);
    HullCull hull(a, b, slack_, n, found_);
    search_.cull(hull);
    for (auto& [reach, id] : found_) {
        const Sphere& s = scene_.objects[id].bound;
        reach = glm::length(s.c - a.c) - s.r - a.r - slack_;
    }
    std::erase_if(found_, [&](const auto& f) { return f.second == target; });
    // [build-blocker-list]
    // Nearest first, so a lookup can stop early
    std::sort(found_.begin(), found_.end());
    BlockerList& list = it->second;
    for (const auto& [reach, id] : found_) {
        list.reach.push_back(reach);
        list.ids.push_back(id);
    }
    ++n.blockerListsBuilt;
    n.blockerListEntries += list.ids.size();
    n.blockerListMax = std::max<std::uint64_t>(n.blockerListMax, list.ids.size());
    return list;
}

}  // namespace rc
