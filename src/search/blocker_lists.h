#pragma once
/// \file
/// \brief Hanrahan's lists of potential blocking spheres, built lazily per pair.
///
/// Any segment from a point of the origin (the eye, a light, or an object's bounding
/// sphere) to a point of the target lies in the convex hull of the two, so only objects
/// whose bounding spheres meet that hull can block it. A list is built the first time a
/// pair is met and kept: no O(n^3) precomputation.
#include <cstdint>
#include <deque>
#include <vector>

#include "analysis/statistics.h"
#include "scene/scene.h"
#include "search/complete_search.h"

namespace rc {

/// One list: the potential blockers, nearest first, and for each the least distance a ray
/// leaving the origin site must travel to reach it: once a hit nearer than that is known,
/// the rest of the list cannot come first (a pruning the paper does not describe).
struct BlockerList {
    std::vector<int> ids;
    std::vector<double> reach;  ///< |c_j - c_origin| - r_j - r_origin, ascending
    /// Longer than a complete search through a grid or hierarchy: its pair is searched
    /// instead (a huge polygon's bounding sphere meets nearly every hull it is part of).
    bool bypass = false;
};

/// Lists longer than this are not worth testing in front of a cheap complete search.
inline constexpr std::size_t kLongList = 32;

/// Lists of potential blockers keyed by (origin site, target site). A site is an object
/// id, the eye (`eyeSite()`), or a light (`lightSite(k)`), each a sphere: a point is a
/// sphere of radius 0.
class BlockerLists {
public:
    /// Candidates come from `search` (all objects for a linear scan, nearby cells for a grid).
    BlockerLists(const Scene& scene, const CompleteSearch& search);

    int eyeSite() const { return scene_.size(); }
    int lightSite(int k) const { return scene_.size() + 1 + k; }
    /// The site a ray starting at `origin` leaves from.
    int originSite(const RayOrigin& origin) const {
        return origin.object >= 0 ? origin.object : eyeSite();
    }
    /// The sphere standing for a site.
    Sphere siteSphere(int site) const;

    /// Every object whose bounding sphere meets the hull of the two sites, the target
    /// excepted; built on first use and counted in `n`.
    const BlockerList& get(int origin, int target, Counters& n);
    /// The list if it was built, else nullptr.
    const std::vector<int>* find(int origin, int target) const;
    std::size_t size() const { return lists_.size(); }

private:
    std::uint64_t key(int origin, int target) const {
        return std::uint64_t(origin) * std::uint64_t(sites_) + std::uint64_t(target);
    }
    const Scene& scene_;
    const CompleteSearch& search_;
    int sites_;
    double slack_;
    std::deque<BlockerList> lists_;  ///< built lists; a deque keeps references stable
    /// Open addressing over keys: slot k holds key + 1 (0: empty) and its list's index
    std::vector<std::uint64_t> slotKeys_;
    std::vector<std::uint32_t> slotLists_;
    std::size_t slot(std::uint64_t key) const;
    /// Where a built list is kept, or nullptr. (A lookup per ray: an open-addressed table.)
    const BlockerList* lookup(std::uint64_t key) const;
    std::vector<std::pair<double, int>> found_;  ///< scratch of the list being built
};

}  // namespace rc
