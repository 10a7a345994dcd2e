#include "search/blocker_lists.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/cone.h"

namespace rc {

namespace {
/// The objects that meet the hull of two spheres (a point is a sphere of radius 0).
/// `meets(id, hull)` has the last word on an object whose bounding sphere meets it.
template <class Meets>
struct HullCull final : SphereCull {
    HullCull(const Sphere& from, const Sphere& to, int target, double slack, std::size_t longest, Counters& n,
             std::vector<std::pair<double, int>>& out, Meets meets)
        : hull(from, to), target(target), longest(longest), n(n), out(out), meets(meets) {
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
        if (id == target || !meets(id, hull)) return;
        out.emplace_back(0.0, id);  // its reach is set once the list is known
        // Longer than a list worth testing: stop, nothing more can matter
        if (out.size() > longest) limit = -kNoHit;
    }
    Hull hull;
    int target;
    std::size_t longest;  ///< stop once the list is longer than this
    Counters& n;
    std::vector<std::pair<double, int>>& out;
    Meets meets;
};

/// The typical object's size: the median radius of the bounding spheres.
double medianRadius(const Scene& scene) {
    std::vector<double> r;
    r.reserve(scene.objects.size());
    for (const Object& o : scene.objects) r.push_back(o.bound.r);
    std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
    return r[r.size() / 2];
}
}  // namespace

BlockerLists::BlockerLists(const Scene& scene, const CompleteSearch& search, bool tiles, bool stepAside)
    : scene_(scene), search_(search), stepAside_(stepAside && search.cheap()) {
    // Rounding only ever adds spheres to a list: widen the hull by a few ulps of the scene
    slack_ = 1e-9 * scene.extent();
    if (tiles && scene.size() > 1) makeTiles();
    sites_ = scene.size() + 1 + int(scene.lights.size()) + int(tileSpheres_.size());
}

void BlockerLists::makeTiles() {
    // [make-tiles]
    // A polygon far larger than the typical object is cut into tiles about twice that size
    constexpr double kLarge = 8.0;  // bounding radius over the median radius that gets tiles
    constexpr int kMostTiles = 32;  // per side
    const double typical = medianRadius(scene_);
    if (!(typical > 0.0)) return;
    tilingOf_.assign(std::size_t(scene_.size()), -1);
    for (int id = 0; id < scene_.size(); ++id) {
        const Object& o = scene_.objects[id];
        if (o.shape != Shape::Polygon || !(o.bound.r > kLarge * typical)) continue;
        const Polygon& poly = scene_.polygons[o.index];
        // A frame in the plane, and the outline's box in it
        Tiling t;
        t.e1 = glm::normalize(poly.vertices[1] - poly.vertices[0]);
        t.e2 = glm::cross(poly.normal, t.e1);
        double u0 = kNoHit, u1 = -kNoHit, v0 = kNoHit, v1 = -kNoHit;
        for (const Vec3& v : poly.vertices) {
            const double u = glm::dot(v - poly.vertices[0], t.e1), w = glm::dot(v - poly.vertices[0], t.e2);
            u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, w), v1 = std::max(v1, w);
        }
        t.corner = poly.vertices[0] + u0 * t.e1 + v0 * t.e2;
        t.nu = std::clamp(int(std::ceil((u1 - u0) / (2.0 * typical))), 1, kMostTiles);
        t.nv = std::clamp(int(std::ceil((v1 - v0) / (2.0 * typical))), 1, kMostTiles);
        t.du = (u1 - u0) / t.nu;
        t.dv = (v1 - v0) / t.nv;
        t.firstTile = int(tileSpheres_.size());
        // Each tile's sphere holds its rectangle, widened by the rounding of hit points
        const double r = 0.5 * std::hypot(t.du, t.dv) * (1.0 + 1e-9) + slack_;
        for (int j = 0; j < t.nv; ++j)
            for (int i = 0; i < t.nu; ++i)
                tileSpheres_.push_back({t.corner + (i + 0.5) * t.du * t.e1 + (j + 0.5) * t.dv * t.e2, r});
        tileObject_.resize(tileSpheres_.size(), id);
        tilingOf_[id] = int(tilings_.size());
        tilings_.push_back(t);
    }
    if (tilings_.empty()) tilingOf_.clear();
    // [make-tiles]
}

bool BlockerLists::tilesUnder(const Tiling& t, const Sphere& a, const Sphere& b, int& i0, int& i1, int& j0,
                              int& j1) const {
    // The hull of a and b lies within the box of the two spheres. A tile's sphere (centred
    // in the plane) can meet it only where that box, widened by the tile's radius, reaches
    // the plane, over the tile's centre
    const double reach = tileSpheres_[std::size_t(t.firstTile)].r + slack_;
    auto extent = [&](const Vec3& axis, double& lo, double& hi) {
        const double ua = glm::dot(a.c - t.corner, axis), ub = glm::dot(b.c - t.corner, axis);
        lo = std::min(ua - a.r, ub - b.r) - reach;
        hi = std::max(ua + a.r, ub + b.r) + reach;
    };
    double lo = 0.0, hi = 0.0;
    extent(glm::cross(t.e1, t.e2), lo, hi);  // height above the plane
    if (lo > 0.0 || hi < 0.0) return false;
    // Tile i's centre is at (i + 1/2) du along e1: those within [lo, hi]
    auto tiles = [](double lo, double hi, double step, int count, int& first, int& last) {
        if (hi < 0.0 || lo > step * count) return false;
        first = std::clamp(int(std::floor(lo / step)), 0, count - 1);
        last = std::clamp(int(std::floor(hi / step)), 0, count - 1);
        return true;
    };
    extent(t.e1, lo, hi);
    if (!tiles(lo, hi, t.du, t.nu, i0, i1)) return false;
    extent(t.e2, lo, hi);
    return tiles(lo, hi, t.dv, t.nv, j0, j1);
}

int BlockerLists::tileSite(const Tiling& t, const Vec3& p) const {
    // The tile holding p; a point just outside the box (rounding) goes to the nearest tile.
    // Below 0 and above the count both clamp, so truncation serves for floor, and no call
    // of libm's floor is made per ray
    const Vec3 d = p - t.corner;
    auto cell = [](double u, int count) { return int(std::clamp(u, 0.0, double(count - 1))); };
    const int i = cell(glm::dot(d, t.e1) / t.du, t.nu);
    const int j = cell(glm::dot(d, t.e2) / t.dv, t.nv);
    return firstTileSite() + t.firstTile + j * t.nu + i;
}

int BlockerLists::siteObject(int site) const {
    if (site < scene_.size()) return site;
    if (site < firstTileSite()) return -1;  // the eye or a light
    return tileObject_[std::size_t(site - firstTileSite())];
}

Sphere BlockerLists::siteSphere(int site) const {
    if (site < scene_.size()) return scene_.objects[site].bound;
    if (site == eyeSite()) return {scene_.camera.from, 0.0};
    if (site >= firstTileSite()) return tileSpheres_[std::size_t(site - firstTileSite())];
    // A spherical light: its shadow rays end anywhere in its sphere
    const Light& light = scene_.lights[std::size_t(site - scene_.size() - 1)];
    return {light.position, light.radius};
}

const std::vector<int>* BlockerLists::find(int origin, int target) const {
    const std::uint32_t number = table_.find(key(origin, target));
    return number == ListTable::kNone || lists_[number].unbuilt ? nullptr : &lists_[number].ids;
}

std::uint32_t BlockerLists::index(int origin, int target, Counters& n) {
    const std::uint64_t id = key(origin, target);
    if (const std::uint32_t number = table_.find(id); number != ListTable::kNone) {
        // The second meeting of a pair: now its list pays
        if (lists_[number].unbuilt) build(number, n);
        return number;
    }
    // A new pair
    const std::uint32_t number = std::uint32_t(lists_.size());
    table_.insert(id, number);
    BlockerList& list = lists_.emplace_back();
    list.origin = origin;
    list.target = target;
    if (stepAside_) {
        // [list-on-second-meeting]
        // In front of a cheap search, a list costs more to build (a hull test per candidate
        // sphere) than a search, so it is built only when its pair comes again: many pairs
        // are met once
        list.unbuilt = true;
        list.bypass = true;
        return number;
        // [list-on-second-meeting]
    }
    build(number, n);
    return number;
}

void BlockerLists::build(std::uint32_t number, Counters& n) {
    BlockerList& list = lists_[number];
    const int origin = list.origin, target = list.target;
    list.bypass = false;
    list.unbuilt = false;
    list.builtAt = builds_++;
    // [build-blocker-list]
    // Every object whose bounding sphere meets the hull of origin and target may block
    const Sphere a = siteSphere(origin);
    const Sphere b = siteSphere(target);
    found_.clear();
    // A tiled polygon blocks only if one of its tiles meets the hull
    auto meets = [&](int id, const Hull& hull) {
        if (tilingOf_.empty() || tilingOf_[id] < 0) return true;
        const Tiling& t = tilings_[tilingOf_[id]];
        int i0, i1, j0, j1;
        if (!tilesUnder(t, a, b, i0, i1, j0, j1)) return false;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const Sphere& tile = tileSpheres_[std::size_t(t.firstTile + j * t.nu + i)];
                ++n.hullTests;
                if (hull.distance(tile.c) - tile.r <= slack_) return true;
            }
        return false;
    };
    // In front of a cheap search, a list longer than kLongList is not tested: building
    // stops there (on balls:4 a long list took a thousand hull tests)
    const std::size_t longest = stepAside_ ? kLongList : found_.max_size();
    HullCull hull(a, b, siteObject(target), slack_, longest, n, found_, meets);
    search_.cull(hull);
    if (found_.size() > longest) {
        // [step-aside-list]
        // Not worth testing: its pair is searched instead
        list.bypass = true;
        ++n.blockerListsBuilt;
        return;
        // [step-aside-list]
    }
    // Nearest first, so a lookup can stop early
    fillNearestFirst(list, scene_, a, slack_, found_);
    // [build-blocker-list]
    ++n.blockerListsBuilt;
    n.blockerListEntries += list.ids.size();
    n.blockerListMax = std::max<std::uint64_t>(n.blockerListMax, list.ids.size());
}

void sortNearestFirst(const Scene& scene, const Sphere& from, double slack, std::vector<std::pair<double, int>>& found) {
    // [nearest-first]
    // No ray from the origin reaches object j before |c_j - c_origin| - r_j - r_origin
    for (auto& [reach, id] : found) {
        const Sphere& s = scene.objects[id].bound;
        reach = glm::length(s.c - from.c) - s.r - from.r - slack;
    }
    std::sort(found.begin(), found.end());
    // [nearest-first]
}

void fillNearestFirst(BlockerList& list, const Scene& scene, const Sphere& from, double slack,
                      std::vector<std::pair<double, int>>& found) {
    sortNearestFirst(scene, from, slack, found);
    list.reach.reserve(found.size());
    list.ids.reserve(found.size());
    for (const auto& [reach, id] : found) {
        list.reach.push_back(reach);
        list.ids.push_back(id);
    }
}

void BlockerLists::truncate(std::size_t n, std::uint64_t builds) {
    if (n > lists_.size() || builds > builds_) throw std::logic_error("BlockerLists::truncate: cannot grow");
    // Lists of pairs met before, built since: as they were
    for (std::size_t k = 0; k < n; ++k) {
        BlockerList& list = lists_[k];
        if (list.unbuilt || list.builtAt < builds) continue;
        BlockerList unbuilt;
        unbuilt.origin = list.origin;
        unbuilt.target = list.target;
        unbuilt.bypass = unbuilt.unbuilt = true;
        list = std::move(unbuilt);
    }
    builds_ = builds;
    if (n == lists_.size()) return;
    lists_.resize(n);
    table_.keepBelow(std::uint32_t(n));
}

}  // namespace rc
