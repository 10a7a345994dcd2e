#include "search/aside_blocker_cache.h"

#include <algorithm>

namespace rc {

Lookup AsideBlockerCache::lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) {
    // [path-steps-aside]
    // A path whose last rays mostly searched anyway steps aside for the next ones, which
    // search at once: no list is looked up or built. Only the last of them loads the
    // entry, for the lookups that follow
    if (e.asideFor > 0 && mode == LookupMode::Full) {
        ++n.steppedAside;
        if (--e.asideFor == 0 && q.kind != RayKind::Shadow) return searchPast(q, &e, mode, n);
        ++n.completeSearches;
        return {true, search_.nearest(q, n), Decision::Uncached, MissReason::None, true};
    }
    if (mode != LookupMode::Full) return BlockerCache::lookup(q, e, mode, n);
    return lookupInWindow(q, e, n);
    // [path-steps-aside]
}

[[gnu::noinline]] Lookup AsideBlockerCache::lookupInWindow(const Query& q, CacheEntry& e, Counters& n) {
    // [path-window]
    // The path's window: if fewer than half of its lookups were answered without a search,
    // it steps aside, each time in a row twice as long
    const Lookup r = BlockerCache::lookup(q, e, LookupMode::Full, n);
    ++e.tried;
    e.spared += !r.searched;
    if (e.tried == kWindow) {
        if (2 * e.spared < e.tried) {
            e.asideFor = std::uint16_t(kRays << e.failed);
            e.failed = std::min<std::uint8_t>(e.failed + 1, kDoublings);
        } else {
            e.failed = 0;
        }
        e.tried = e.spared = 0;
    }
    return r;
    // [path-window]
}

}  // namespace rc
