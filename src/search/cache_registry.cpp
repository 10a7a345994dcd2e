#include "search/cache_registry.h"

#include <stdexcept>

#include "search/aside_blocker_cache.h"
#include "search/blocker_cache.h"
#include "search/cylinder_cache.h"
#include "search/no_cache.h"

namespace rc {

namespace {

/// blocker+ or blocker+dir: in front of a cheap search, whole paths step aside where the
/// cache does not pay
std::unique_ptr<CacheStrategy> blockerPlus(const Scene& scene, const CompleteSearch& search,
                                           BlockerCache::Variant variant) {
    if (search.cheap()) return std::make_unique<AsideBlockerCache>(scene, search, variant);
    return std::make_unique<BlockerCache>(scene, search, variant);
}

Registry<CacheInfo>& registry() {
    // [cache-registry]
    // The built-in caches, in CacheKind's order: their index is their kind
    static Registry<CacheInfo> r = [] {
        Registry<CacheInfo> b;
        b.add({"none", "no cache: every ray makes a complete search",
               [](const Scene& s, const CompleteSearch& c) { return std::make_unique<NoCache>(s, c); },
               Deferral::Never});
        b.add({"cylinder", "Speer, DeRose and Barsky's cylinder of safety",
               [](const Scene& s, const CompleteSearch& c) { return std::make_unique<CylinderCache>(s, c); },
               Deferral::Always});
        b.add({"blocker", "Hanrahan's blocker lists, RayCache's reading of the paper's cache",
               [](const Scene& s, const CompleteSearch& c) {
                   return std::make_unique<BlockerCache>(s, c, BlockerCache::Variant::Paper);
               },
               Deferral::Always, true});
        b.add({"blocker+", "blocker lists with RayCache's additions",
               [](const Scene& s, const CompleteSearch& c) { return blockerPlus(s, c, BlockerCache::Variant::Plus); },
               Deferral::UnlessCheapSearch, true});
        b.add({"blocker+dir", "blocker+, its misses answered from direction lists",
               [](const Scene& s, const CompleteSearch& c) {
                   return blockerPlus(s, c, BlockerCache::Variant::Directions);
               },
               Deferral::Never, true, false});
        return b;
    }();
    // [cache-registry]
    return r;
}

}  // namespace

const Registry<CacheInfo>& cacheRegistry() { return registry(); }

CacheKind registerCache(CacheInfo info) {
    if (!info.make) throw std::logic_error("cache '" + info.name + "' has no factory");
    return CacheKind(registry().add(std::move(info)));
}

const CacheInfo& cacheInfo(CacheKind kind) { return registry()[std::size_t(kind)]; }

std::vector<CacheKind> sweptCacheKinds() {
    std::vector<CacheKind> out;
    for (CacheKind c : allCacheKinds())
        if (cacheInfo(c).inSweeps) out.push_back(c);
    return out;
}

}  // namespace rc
