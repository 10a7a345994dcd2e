#include "search/cache_strategy.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "search/cache_registry.h"

namespace rc {

std::string_view toString(CacheKind k) {
    const auto& r = cacheRegistry();
    const auto i = std::size_t(k);
    return i < r.size() ? std::string_view(r[i].name) : std::string_view("?");
}

std::vector<CacheKind> allCacheKinds() {
    std::vector<CacheKind> out;
    for (std::size_t i = 0; i < cacheRegistry().size(); ++i) out.push_back(CacheKind(i));
    return out;
}

std::optional<CacheKind> parseCacheKind(std::string_view s) {
    const int i = cacheRegistry().indexOf(s);
    if (i < 0) return std::nullopt;
    return CacheKind(i);
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

std::unique_ptr<CacheStrategy> makeStrategy(CacheKind kind, const Scene& scene,
                                            const CompleteSearch& search) {
    return cacheInfo(kind).make(scene, search);
}

}  // namespace rc
