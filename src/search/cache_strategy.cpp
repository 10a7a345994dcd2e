#include "search/cache_strategy.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "search/aside_blocker_cache.h"
#include "search/blocker_cache.h"
#include "search/cylinder_cache.h"
#include "search/no_cache.h"

namespace rc {

std::string_view toString(CacheKind k) {
    switch (k) {
        case CacheKind::None: return "none";
        case CacheKind::Cylinder: return "cylinder";
        case CacheKind::Blocker: return "blocker";
        case CacheKind::BlockerPlus: return "blocker+";
        case CacheKind::BlockerDirections: return "blocker+dir";
    }
    return "?";
}

std::optional<CacheKind> parseCacheKind(std::string_view s) {
    for (CacheKind k : allCacheKinds())
        if (toString(k) == s) return k;
    return std::nullopt;
}

CacheStrategy::CacheStrategy(const Scene& scene, const CompleteSearch& search)
    : scene_(scene), search_(search) {
    slack_ = 1e-9 * scene.extent();
}

Lookup CacheStrategy::searchAndReload(const Query& q, CacheEntry& e, MissReason why, Counters& n) {
    // [search-and-reload]
    // A miss: search the whole scene, then load the cache with what was found
    ++n.completeSearches;
    const Answer a = search_.nearest(q, n);
    reload(q, a, e, n);
    return {true, a, Decision::Miss, why, true};
    // [search-and-reload]
}

MissReason CacheStrategy::unusable(const Query& q, const CacheEntry& e) {
    if (e.state == CacheEntry::State::Empty) return MissReason::Cold;
    if (e.state == CacheEntry::State::Flushed) return MissReason::Flushed;
    if (!(e.origin == q.origin)) return MissReason::OriginChanged;
    return MissReason::None;
}

std::unique_ptr<CacheStrategy> makeStrategy(CacheKind kind, const Scene& scene,
                                            const CompleteSearch& search) {
    switch (kind) {
        case CacheKind::None: return std::make_unique<NoCache>(scene, search);
        case CacheKind::Cylinder: return std::make_unique<CylinderCache>(scene, search);
        case CacheKind::Blocker: return std::make_unique<BlockerCache>(scene, search, BlockerCache::Variant::Paper);
        case CacheKind::BlockerPlus:
        case CacheKind::BlockerDirections: {
            const auto variant =
                kind == CacheKind::BlockerPlus ? BlockerCache::Variant::Plus : BlockerCache::Variant::Directions;
            // In front of a cheap search, whole paths step aside where the cache does not pay
            if (search.cheap()) return std::make_unique<AsideBlockerCache>(scene, search, variant);
            return std::make_unique<BlockerCache>(scene, search, variant);
        }
    }
    return nullptr;
}

}  // namespace rc
