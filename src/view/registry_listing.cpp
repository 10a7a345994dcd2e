#include "view/registry_listing.h"

#include <stdexcept>

#include "order/order_registry.h"
#include "scene/builtin_scenes.h"
#include "search/cache_registry.h"
#include "search/search_registry.h"
#include "view/overlay_registry.h"

namespace rc {

namespace {

/// One registry's entries: {name, description} and what `extra` adds
template <class Entry, class Extra>
nlohmann::json listing(const Registry<Entry>& r, Extra extra) {
    nlohmann::json out = nlohmann::json::array();
    for (const Entry& e : r.entries()) {
        nlohmann::json j{{"name", e.name}, {"description", e.description}};
        extra(e, j);
        out.push_back(j);
    }
    return out;
}

}  // namespace

nlohmann::json registryListing(std::string_view what) {
    if (what == "caches")
        return listing(cacheRegistry(), [](const CacheInfo& c, nlohmann::json& j) {
            j["blocker_lists"] = c.blockerLists;
            j["in_sweeps"] = c.inSweeps;
        });
    if (what == "orders") return listing(orderRegistry(), [](const OrderInfo&, nlohmann::json&) {});
    if (what == "searches")
        return listing(searchRegistry(),
                       [](const SearchInfo& s, nlohmann::json& j) { j["comparison_only"] = s.comparisonOnly; });
    if (what == "overlays")
        return listing(overlayRegistry(), [](const OverlayInfo& o, nlohmann::json& j) {
            j["aliases"] = o.aliases;
            j["in_page"] = o.inPage;
        });
    if (what == "scenes") {
        nlohmann::json out = nlohmann::json::array();
        for (const BuiltinInfo& b : builtinScenes())
            out.push_back({{"name", b.name}, {"description", b.description}, {"sizes", b.sizes}});
        return out;
    }
    throw std::invalid_argument("no registry of '" + std::string(what) +
                                "': caches, orders, searches, overlays or scenes");
}

}  // namespace rc
