// A toy cache, added the way docs/pages/adding_a_cache.md says, in one file: it is compiled
// into this folder's test binaries only (a CLI built with it, and its test), never into
// raycache_core, and registers itself with a static registrar. It remembers nothing: every
// lookup is a cold miss, answered by a complete search, so every image it gives is the
// uncached one.
#include "search/cache_registry.h"

namespace {

using namespace rc;

// [toy-cache]
class ToyCache final : public CacheStrategy {
public:
    using CacheStrategy::CacheStrategy;
    CacheKind kind() const override;
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override {
        // A cheap lookup cannot answer without searching: give up (the order defers the ray)
        if (mode == LookupMode::CheapOnly) return {false, {}, Decision::Miss, MissReason::Cold};
        return searchAndReload(q, e, MissReason::Cold, n);
    }

protected:
    // Nothing is kept: the entry stays empty, so the next lookup is cold again
    void reload(const Query&, const Answer&, CacheEntry&, Counters&) override {}
};

const CacheRegistrar kToy{{"toy", "a toy that remembers nothing (docs/pages/adding_a_cache.md)",
                           [](const Scene& s, const CompleteSearch& c) { return std::make_unique<ToyCache>(s, c); },
                           Deferral::Never}};

CacheKind ToyCache::kind() const { return kToy.kind; }
// [toy-cache]

}  // namespace
