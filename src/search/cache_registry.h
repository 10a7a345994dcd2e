#pragma once
/// \file
/// \brief The caches, registered once: each one's name (`--cache`), one line that describes
/// it, what makes it, and how breadth-first order treats its misses. `--cache`'s choices, the
/// GUI's and the page's menus, `table1` and `bench` read this list (docs/pages/adding_a_cache.md).
///
/// RayCache's own addition; the paper names two caches, this list holds them and RayCache's.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/registry.h"
#include "search/cache_strategy.h"

namespace rc {

/// Does breadth-first order ask a cache cheaply first and defer a ray it cannot answer
/// (order/deferral_policy.h)?
enum class Deferral {
    Never,              ///< every ray is asked fully when its turn comes
    Always,             ///< every ray is asked cheaply first
    UnlessCheapSearch,  ///< cheaply first only in front of the linear scan
};

/// One cache as the registry holds it.
struct CacheInfo {
    std::string name;         ///< as `--cache` takes it, e.g. "blocker+"
    std::string description;  ///< one line, for help texts, menus' tooltips and `raycache list`
    /// Makes the cache for a scene and the complete search behind it (both outlive it).
    std::function<std::unique_ptr<CacheStrategy>(const Scene&, const CompleteSearch&)> make;
    Deferral deferral = Deferral::Never;
    bool blockerLists = false;  ///< it builds blocker lists (left_out counts them)
    bool inSweeps = true;       ///< `coherence` and `convergence` sweep it
};

/// Every cache, the built-in ones first (cache_registry.cpp), then any a registrar adds.
const Registry<CacheInfo>& cacheRegistry();

/// Registers a cache; returns its kind (its index in the registry).
/// \throws std::logic_error when its name is taken or it has no factory.
CacheKind registerCache(CacheInfo info);

/// Registers a cache when the program starts: `static const CacheRegistrar toy{{"toy", ...}};`
/// in a file the program is linked with (an object file, not one of a static library that
/// nothing else refers to: the linker would leave that out).
struct CacheRegistrar {
    explicit CacheRegistrar(CacheInfo info) : kind(registerCache(std::move(info))) {}
    CacheKind kind;
};

/// The registry's entry of `kind`. \throws std::out_of_range for a kind never registered.
const CacheInfo& cacheInfo(CacheKind kind);

/// The caches `coherence` and `convergence` sweep (CacheInfo::inSweeps), in registry order.
/// Ask after the program has started (every registrar has run by then).
std::vector<CacheKind> sweptCacheKinds();

}  // namespace rc
