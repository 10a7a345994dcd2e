#include "search/no_cache.h"

namespace rc {

Lookup NoCache::lookup(const Query& q, CacheEntry&, LookupMode, Counters& n) {
    ++n.completeSearches;
    return {true, search_.nearest(q, n), Decision::Uncached, MissReason::None, true};
}

}  // namespace rc
