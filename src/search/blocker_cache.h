#pragma once
/// \file
/// \brief Hanrahan's cache: the last object hit and its list of potential blockers.
#include <memory>
#include <vector>

#include "search/cache_strategy.h"
#include "search/cylinder_of_safety.h"
#include "search/direction_lists.h"

namespace rc {

class PackedSpheres;

/// Hanrahan (1986): the cache holds the last object hit; a ray hits the cache when it
/// hits that object and none of the potential blockers between its origin and that
/// object.
///
/// Three variants share this code:
/// - `Variant::Paper` (`--cache blocker`) is the paper's cache as RayCache reads it: every
///   list entry is tested, and rays that hit nothing keep the Speer-DeRose-Barsky
///   cylinder of safety, as the paper prescribes. Four readings are RayCache's, not the
///   paper's text, each exact: a ray that hits a listed blocker first is answered by that
///   blocker, without a complete search (the paper: "Each cache miss causes all the
///   objects to be searched"); a shadow ray is answered by testing the list of the hull of
///   its origin and its light (the cone from the light), without a complete search;
///   lists are kept per (origin, target) pair and shared by every path and pixel; and
///   they are found through a hierarchy of bounding spheres, with `--accel linear` too
///   (LinearSearch).
/// - `Variant::Plus` (`--cache blocker+`) adds RayCache's improvements, each exact:
///   lists kept nearest first and left early once a nearer hit is known; rays that hit
///   nothing keep the cone of directions around the last such ray that no object's
///   silhouette enters (seen from anywhere in the origin's sphere); entries remembered per
///   origin, so a ray from an object met before tries the object its rays last hit
///   before a complete search; large polygons cut into tiles, each its own
///   site (BlockerLists); and, in front of a grid or a hierarchy, an entry steps aside
///   (searches) where testing its list would cost more than the search, and so does a
///   whole ray-tree path whose rays mostly search anyway (AsideBlockerCache).
/// - `Variant::Directions` (`--cache blocker+dir`) is blocker+ whose misses, in front of
///   the linear scan, test the objects listed for the ray's direction from its site
///   (DirectionLists) instead of the whole scene. Rays that hit nothing keep no cylinder
///   or cone: their list answers them. No ray is deferred (order/deferral_policy.h): a
///   miss is cheap.
class BlockerCache : public CacheStrategy {
public:
    enum class Variant { Paper, Plus, Directions };
    BlockerCache(const Scene& scene, const CompleteSearch& search, Variant variant);
    ~BlockerCache() override;
    CacheKind kind() const override {
        return directed_ ? CacheKind::BlockerDirections : plus_ ? CacheKind::BlockerPlus : CacheKind::Blocker;
    }
    /// The lookup of one ray (AsideBlockerCache adds the stepping aside of whole paths).
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override;
    const BlockerLists* blockerLists() const override { return &lists_; }
    std::unique_ptr<StrategyCheckpoint> checkpoint() const override;
    void restore(const StrategyCheckpoint* saved) override;

protected:
    void reload(const Query& q, const Answer& a, CacheEntry& e, Counters& n) override;

    /// A ray whose list is not worth testing (BlockerList::bypass): a complete search,
    /// answered as uncached; the entry, if any, is loaded with what it found. In CheapOnly
    /// mode it searches nothing: the ray is deferred.
    Lookup searchPast(const Query& q, CacheEntry* e, LookupMode mode, Counters& n);

private:
    Lookup probe(const Query& q, CacheEntry& e, LookupMode mode, Counters& n);
    Lookup probeEmpty(const Query& q, CacheEntry& e, LookupMode mode, Counters& n);
    Lookup shadow(const Query& q, CacheEntry& e, MissReason unusable, LookupMode mode, Counters& n);
    void buildCone(CacheEntry& e, Counters& n) const;
    /// Tests the potential blockers of `list` against `q`, keeping the nearest in `best`.
    void testBlockers(const Query& q, const BlockerList& list, Answer& best, Counters& n) const;
    /// Blocker+: keeps the entry under its origin and brings back the one kept for the
    /// query's origin, if any. Returns whether the entry now answers for `q.origin`.
    bool recall(const Query& q, CacheEntry& e);
    /// A ray the entry cannot answer: blocker+dir tests the objects listed in its direction
    /// (DirectionLists), everything else searches the whole scene; the entry is reloaded.
    Lookup searchMissed(const Query& q, CacheEntry& e, MissReason why, Counters& n);

    bool plus_;
    bool directed_;  ///< blocker+dir
    BlockerLists lists_;
    /// The paper: rays that hit nothing keep a cylinder of safety (blocker+: those from an object)
    CylinderOfSafety cylinders_;
    /// Blocker+: the entry last used for rays of each (origin site, kind), 3 kinds (shadow
    /// rays keep no entry): its place in kept_, or kNotKept. Only origins met take room in
    /// kept_, so a scene of many objects sets up no entry before its first ray
    std::vector<std::uint32_t> byOrigin_;
    std::vector<CacheEntry> kept_;
    static constexpr std::uint32_t kNotKept = std::uint32_t(-1);
    /// Blocker+dir in front of the linear scan: the objects in each direction from each site
    /// (elsewhere blocker+dir is blocker+)
    std::unique_ptr<DirectionLists> directions_;
    /// Every sphere by id, for testing lists four at a time (search/packed_spheres.h, which
    /// tests objects and so holds solution regions, is included only by the sources that test)
    std::unique_ptr<const PackedSpheres> packed_;
};

}  // namespace rc
