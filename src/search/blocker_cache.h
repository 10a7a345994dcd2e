#pragma once
/// \file
/// \brief Hanrahan's cache: the last object hit and its list of potential blockers.
#include "search/cache_strategy.h"

namespace rc {

/// Hanrahan (1986): the cache holds the last object hit; a ray hits the cache when it
/// hits that object and none of the potential blockers between its origin and that
/// object. All misses mean a new object was met. Shadow rays are answered from the list
/// of the hull of their origin and their light, which holds every object that could
/// stand in the way, so they never need a complete search. Rays that hit nothing keep the
/// cone of directions around the last such ray that no object's silhouette enters, seen
/// from anywhere in the origin's sphere (the eye is a sphere of radius 0); where another
/// object touches the origin there is no such cone and the cylinder of safety is used.
class BlockerCache final : public CacheStrategy {
public:
    BlockerCache(const Scene& scene, const CompleteSearch& search);
    CacheKind kind() const override { return CacheKind::Blocker; }
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override;
    const BlockerLists* blockerLists() const override { return &lists_; }

protected:
    void reload(const Query& q, const Answer& a, CacheEntry& e, Counters& n) override;

private:
    Lookup probe(const Query& q, CacheEntry& e, Counters& n);
    Lookup shadow(const Query& q, const CacheEntry& e, MissReason unusable, Counters& n);
    void buildCone(CacheEntry& e, Counters& n) const;
    /// A ray whose list is not worth testing (BlockerList::bypass): a complete search,
    /// answered as uncached; the entry, if any, is loaded with what it found.
    Lookup searchPast(const Query& q, CacheEntry* e, Counters& n);
    BlockerLists lists_;
};

}  // namespace rc
