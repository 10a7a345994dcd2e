#pragma once
/// \file
/// \brief The interchangeable answers to "what does this ray hit first?": no cache, the
/// Speer-DeRose-Barsky cylinder of safety, Hanrahan's blocker lists, and RayCache's two
/// extensions of them (blocker+ and blocker+dir).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "search/blocker_lists.h"
#include "search/cache_tree.h"
#include "search/complete_search.h"

namespace rc {

/// Which cache answers ray queries: an index into the cache registry (search/cache_registry.h),
/// which holds the built-in ones below in this order and then any a registrar adds.
enum class CacheKind : int {
    None,         ///< every ray searches
    Cylinder,     ///< Speer, DeRose and Barsky's cylinder of safety
    Blocker,      ///< Hanrahan's blocker lists, with RayCache's readings of the paper (BlockerCache)
    BlockerPlus,  ///< blocker lists with RayCache's additions (`blocker+`)
    BlockerDirections,  ///< blocker+ whose misses test the objects listed in their direction (`blocker+dir`)
};
/// The registered name of a cache ("?" for a kind never registered).
std::string_view toString(CacheKind k);
/// Every registered cache kind, in the order tables list them.
std::vector<CacheKind> allCacheKinds();
std::optional<CacheKind> parseCacheKind(std::string_view s);

/// How far a lookup may go.
enum class LookupMode {
    Full,       ///< answer every query; on a miss, search and reload the entry
    CheapOnly,  ///< answer from the cache or give up: never search, never reload
};

/// The outcome of one lookup.
///
/// Its fields are laid out flat in sixteen bytes, so that a lookup is returned in two
/// registers: a larger one is returned in memory, and its caller reads it back in wide loads
/// from the callee's narrow stores still in flight, which stalls.
struct Lookup {
    Lookup() = default;
    Lookup(bool known, const Answer& a, Decision d = Decision::Uncached, MissReason why = MissReason::None,
           bool searched = false)
        : t(a.t), object(a.object), known(known), decision(d), reason(why), searched(searched) {}
    /// The object hit first (or -1), and where.
    Answer answer() const { return {object, t}; }

    double t = kNoHit;  ///< the answer's distance
    int object = -1;    ///< the answer's object
    bool known = false;  ///< false: CheapOnly gave up (the ray is deferred)
    Decision decision = Decision::Uncached;
    MissReason reason = MissReason::None;
    bool searched = false;  ///< a complete search was made
};
static_assert(sizeof(Lookup) == 16, "a lookup fits in two registers");

/// What a cache strategy knows beyond the cache tree's entries, as it was at a checkpoint
/// of a stepping render (see CacheStrategy::checkpoint).
struct StrategyCheckpoint {
    virtual ~StrategyCheckpoint() = default;
    /// Bytes it holds.
    virtual std::size_t bytes() const = 0;
};

/// A cache strategy: looks up a query in its cache entry, falling back on the complete
/// search. Every answer it gives equals the complete search's, object and distance.
class CacheStrategy {
public:
    CacheStrategy(const Scene& scene, const CompleteSearch& search);
    virtual ~CacheStrategy() = default;
    virtual CacheKind kind() const = 0;
    /// Answers `q` using (and, in Full mode, updating) the cache entry of its path.
    virtual Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) = 0;
    /// Can a cheap lookup fail? (Not without a cache: every lookup searches.)
    virtual bool caches() const { return true; }
    /// The blocker lists, for strategies that have them.
    virtual const BlockerLists* blockerLists() const { return nullptr; }

    // [strategy-checkpoint]
    /// What the strategy keeps beyond the entries it is handed (null: nothing, as for no
    /// cache and the cylinder cache, whose whole state is in the cache tree).
    virtual std::unique_ptr<StrategyCheckpoint> checkpoint() const { return nullptr; }
    /// Goes back to a checkpoint this strategy took (null: one it took with nothing in
    /// it). The strategy must be at or past it: what it learnt since is forgotten.
    virtual void restore(const StrategyCheckpoint* saved) { (void)saved; }
    // [strategy-checkpoint]

protected:
    /// A complete search, counted, and the entry reloaded with its answer.
    Lookup searchAndReload(const Query& q, CacheEntry& e, MissReason why, Counters& n);
    virtual void reload(const Query& q, const Answer& a, CacheEntry& e, Counters& n) = 0;
    /// Why an entry cannot answer this query at all, or None when it may (inline: asked
    /// once per lookup).
    static MissReason unusable(const Query& q, const CacheEntry& e) {
        if (e.state == CacheEntry::State::Empty) return MissReason::Cold;
        if (e.state == CacheEntry::State::Flushed) return MissReason::Flushed;
        if (!(e.origin == q.origin)) return MissReason::OriginChanged;
        return MissReason::None;
    }
    const Scene& scene_;
    const CompleteSearch& search_;
    double slack_;  ///< a few ulps of the scene's size: shrinks cylinders and cones
};

/// Makes the strategy of a kind (its registry entry's factory).
std::unique_ptr<CacheStrategy> makeStrategy(CacheKind kind, const Scene& scene,
                                            const CompleteSearch& search);

}  // namespace rc
