#include "search/cylinder_cache.h"

namespace rc {

Lookup CylinderCache::lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) {
    // [cylinder-lookup]
    MissReason why = unusable(q, e);
    if (why == MissReason::None) {
        // The cylinder is built the first time a ray may fit in it
        const Lookup probe = cylinders_.probe(q, e, n);
        if (probe.known) return probe;
        why = probe.reason;
    }
    // A miss: defer the ray, or search and rebuild the cylinder
    if (mode == LookupMode::CheapOnly) return {false, {}, Decision::Miss, why};
    return searchAndReload(q, e, why, n);
    // [cylinder-lookup]
}

void CylinderCache::reload(const Query& q, const Answer& a, CacheEntry& e, Counters&) {
    e.state = CacheEntry::State::Loaded;
    e.origin = q.origin;
    e.object = a.object;
    cylinders_.keep(q, a, e);
}

}  // namespace rc
