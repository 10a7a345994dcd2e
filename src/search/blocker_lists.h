#pragma once
/// \file
/// \brief Hanrahan's lists of potential blocking spheres, built lazily per pair.
///
/// Any segment from a point of the origin (the eye, a light, or an object's bounding
/// sphere) to a point of the target lies in the convex hull of the two, so only objects
/// whose bounding spheres meet that hull can block it. A list is built the first time a
/// pair is met and kept, with no precomputation (the paper: "the naive algorithm to do
/// this is of O(n^3)").
#include <cstdint>
#include <deque>
#include <vector>

#include "scene/scene.h"
#include "search/complete_search.h"
#include "search/counters.h"
#include "search/list_table.h"
#include "search/query.h"

namespace rc {

/// One list: the potential blockers, nearest first, and for each the least distance a ray
/// leaving the origin site must travel to reach it: once a hit nearer than that is known,
/// the rest of the list cannot come first (a pruning the paper does not describe).
struct BlockerList {
    int origin = -1, target = -1;  ///< its pair of sites
    std::vector<int> ids;
    std::vector<double> reach;  ///< |c_j - c_origin| - r_j - r_origin, ascending
    /// Longer than a complete search through a grid or hierarchy: its pair is searched
    /// instead (a huge polygon's bounding sphere meets nearly every hull it is part of),
    /// and the list is left empty
    bool bypass = false;
    /// Blocker+ in front of a cheap search: not built yet (its pair was met once), so empty
    /// and bypassed
    bool unbuilt = false;
    std::uint64_t builtAt = 0;  ///< how many lists were built before it (BlockerLists::builds())
};

/// Sorts the objects of `found` nearest first, each distance overwritten by the object's
/// reach from the sphere `from`, less `slack`.
void sortNearestFirst(const Scene& scene, const Sphere& from, double slack, std::vector<std::pair<double, int>>& found);

/// Fills `list` with the objects of `found` sorted by sortNearestFirst(), with their reaches.
void fillNearestFirst(BlockerList& list, const Scene& scene, const Sphere& from, double slack,
                      std::vector<std::pair<double, int>>& found);

/// Lists longer than this are not worth testing in front of a cheap complete search.
inline constexpr std::size_t kLongList = 32;

/// Lists of potential blockers keyed by (origin site, target site). A site is an object
/// id, the eye (`eyeSite()`), a light (`lightSite(k)`: its sphere, when it has a radius),
/// or a tile of a large polygon, each a sphere: a point is a sphere of radius 0.
///
/// Tiles (blocker+): the paper bounds every object by a sphere, and a large polygon's
/// sphere is a poor fit: the hull from the eye to a ground quad's sphere holds every
/// object, and the quad's sphere meets nearly every hull. With tiles, a polygon much
/// larger than the typical object is cut into a grid of tiles in its plane, each bounded
/// by its own small sphere. A ray that hits the polygon (or leaves it) at point p uses the
/// site of the tile holding p: every segment from the origin to p lies in the hull of the
/// origin and that tile. And the polygon is a potential blocker of a hull only if one of
/// its tiles meets it.
class BlockerLists {
public:
    /// Candidates come from `search` (all objects for a linear scan, nearby cells for a
    /// grid). `tiles`: cut large polygons into tiles (blocker+). `stepAside`: in front of a
    /// cheap search, a list longer than kLongList is left empty and marked `bypass`, its
    /// building stopped there; and a pair met for the first time gets no list yet (bypassed
    /// too): it is built when the pair is met again (blocker+).
    BlockerLists(const Scene& scene, const CompleteSearch& search, bool tiles = false, bool stepAside = false);

    int eyeSite() const { return scene_.size(); }
    int lightSite(int k) const { return scene_.size() + 1 + k; }
    /// The site a ray starting at `origin` leaves from (without tiles).
    int originSite(const RayOrigin& origin) const {
        return origin.object >= 0 ? origin.object : eyeSite();
    }
    /// The site the ray of `q` leaves from: its tile, when it leaves a tiled polygon.
    int originSite(const Query& q) const {
        return q.origin.object >= 0 ? pointSite(q.origin.object, q.ray.o) : eyeSite();
    }
    /// The site of point `p` on object `id`: its tile, or the object itself.
    int pointSite(int id, const Vec3& p) const {
        return tilingOf_.empty() || tilingOf_[id] < 0 ? id : tileSite(tilings_[tilingOf_[id]], p);
    }
    /// The object a site stands for (-1: the eye or a light).
    int siteObject(int site) const;
    /// The sphere standing for a site.
    Sphere siteSphere(int site) const;
    /// Tiles made (0 without tiles).
    std::size_t tiles() const { return tileSpheres_.size(); }
    /// How many sites there are: objects, the eye, the lights, then the tiles.
    int sites() const { return sites_; }

    /// Every object whose bounding sphere meets the hull of the two sites, the target
    /// excepted; built on first use and counted in `n`.
    const BlockerList& get(int origin, int target, Counters& n) { return lists_[index(origin, target, n)]; }
    /// The same, trying first the list numbered `memo` (a path's rays mostly ask for the
    /// pair its last ray asked for: no hashing then), and leaving the list's number there.
    const BlockerList& get(int origin, int target, std::uint32_t& memo, Counters& n) {
        if (memo < lists_.size()) {
            const BlockerList& last = lists_[memo];
            if (last.origin == origin && last.target == target && !last.unbuilt) return last;
        }
        memo = index(origin, target, n);
        return lists_[memo];
    }
    /// The list if it was built, else nullptr.
    const std::vector<int>* find(int origin, int target) const;
    /// Pairs met (their lists built or not).
    std::size_t size() const { return lists_.size(); }
    /// Lists built so far.
    std::uint64_t builds() const { return builds_; }
    /// Forgets every pair but the first `n` met (n <= size()), and unbuilds the lists built
    /// after the first `builds`: the lists are a log that only grows, so a checkpoint of a
    /// render keeps its length, not a copy. Slow (it rebuilds the table); never called
    /// while rendering.
    void truncate(std::size_t n, std::uint64_t builds);

private:
    /// A polygon cut into nu x nv tiles over its box in the plane (corner, e1, e2).
    struct Tiling {
        int firstTile = 0;  ///< its first tile in tileSpheres_
        Vec3 corner{0.0}, e1{0.0}, e2{0.0};
        double du = 0.0, dv = 0.0;
        int nu = 1, nv = 1;
    };
    int tileSite(const Tiling& t, const Vec3& p) const;
    /// The tiles of `t` that can meet the hull of a and b: [i0, i1] x [j0, j1], or none.
    bool tilesUnder(const Tiling& t, const Sphere& a, const Sphere& b, int& i0, int& i1, int& j0, int& j1) const;
    int firstTileSite() const { return scene_.size() + 1 + int(scene_.lights.size()); }
    void makeTiles();
    std::uint64_t key(int origin, int target) const {
        return std::uint64_t(origin) * std::uint64_t(sites_) + std::uint64_t(target);
    }
    const Scene& scene_;
    const CompleteSearch& search_;
    bool stepAside_;  ///< lists longer than kLongList are left empty, not tested
    double slack_;
    std::vector<int> tilingOf_;       ///< per object: its tiling, or -1 (empty: no tiles)
    std::vector<Tiling> tilings_;
    std::vector<Sphere> tileSpheres_;  ///< per tile, whose site is firstTileSite() + its index
    std::vector<int> tileObject_;      ///< per tile, the polygon it belongs to
    int sites_;
    std::deque<BlockerList> lists_;  ///< built lists; a deque keeps references stable
    ListTable table_;  ///< each pair's list by number
    /// The number of the pair's list, built first if need be.
    std::uint32_t index(int origin, int target, Counters& n);
    /// Fills list `number` with its potential blockers.
    void build(std::uint32_t number, Counters& n);
    std::vector<std::pair<double, int>> found_;  ///< scratch of the list being built
    std::uint64_t builds_ = 0;
};

}  // namespace rc
