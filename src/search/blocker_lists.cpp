#include "search/blocker_lists.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/cone.h"

namespace rc {

namespace {
/// The objects that meet the hull of two spheres (a point is a sphere of radius 0).
struct HullCull final : SphereCull {
    HullCull(const Sphere& from, const Sphere& to, int target, double slack, Counters& n,
             std::vector<std::pair<double, int>>& out)
        : hull(from, to), target(target), n(n), out(out) {
        // The hull lies within the larger radius of the segment between the centres
        a = from.c;
        b = to.c;
        radius = std::max(from.r, to.r) + slack;
        limit = slack;
    }
    // The hull's distance function is 1-Lipschitz: a lower bound for any sphere inside s
    double distance(const Sphere& s) override {
        ++n.hullTests;
        return hull.distance(s.c) - s.r;
    }
    void found(int id, double) override {
        if (id != target) out.emplace_back(0.0, id);  // its reach is set once the list is known
    }
    Hull hull;
    int target;
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

std::size_t BlockerLists::slot(std::uint64_t key) const {
    // Fibonacci hashing into a power-of-two table, then the next free or matching slot
    const std::size_t mask = slotKeys_.size() - 1;
    std::size_t k = std::size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & mask;
    while (slotKeys_[k] != 0 && slotKeys_[k] != key + 1) k = (k + 1) & mask;
    return k;
}

const BlockerList* BlockerLists::lookup(std::uint64_t key) const {
    if (slotKeys_.empty()) return nullptr;
    const std::size_t k = slot(key);
    return slotKeys_[k] == 0 ? nullptr : &lists_[slotLists_[k]];
}

const std::vector<int>* BlockerLists::find(int origin, int target) const {
    const BlockerList* list = lookup(key(origin, target));
    return list ? &list->ids : nullptr;
}

const BlockerList& BlockerLists::get(int origin, int target, Counters& n) {
    const std::uint64_t id = key(origin, target);
    if (const BlockerList* list = lookup(id)) return *list;
    // A new pair: keep the table at most half full
    if (2 * (lists_.size() + 1) > slotKeys_.size()) {
        std::vector<std::uint64_t> keys = std::move(slotKeys_);
        std::vector<std::uint32_t> lists = std::move(slotLists_);
        slotKeys_.assign(std::max<std::size_t>(64, 2 * keys.size()), 0);
        slotLists_.assign(slotKeys_.size(), 0);
        for (std::size_t k = 0; k < keys.size(); ++k) {
            if (keys[k] == 0) continue;
            const std::size_t to = slot(keys[k] - 1);
            slotKeys_[to] = keys[k];
            slotLists_[to] = lists[k];
        }
    }
    const std::size_t k = slot(id);
    slotKeys_[k] = id + 1;
    slotLists_[k] = std::uint32_t(lists_.size());
    BlockerList& list = lists_.emplace_back();
    // [build-blocker-list]
    // Every object whose bounding sphere meets the hull of origin and target may block
    const Sphere a = siteSphere(origin);
    const Sphere b = siteSphere(target);
    found_.clear();
    HullCull hull(a, b, target, slack_, n, found_);
    search_.cull(hull);
    for (auto& [reach, id] : found_) {
        const Sphere& s = scene_.objects[id].bound;
        reach = glm::length(s.c - a.c) - s.r - a.r - slack_;
    }
    // [build-blocker-list]
    // Nearest first, so a lookup can stop early
    std::sort(found_.begin(), found_.end());
    for (const auto& [reach, id] : found_) {
        list.reach.push_back(reach);
        list.ids.push_back(id);
    }
    list.bypass = search_.cheap() && list.ids.size() > kLongList;
    ++n.blockerListsBuilt;
    n.blockerListEntries += list.ids.size();
    n.blockerListMax = std::max<std::uint64_t>(n.blockerListMax, list.ids.size());
    return list;
}

}  // namespace rc
