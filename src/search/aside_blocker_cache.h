#pragma once
/// \file
/// \brief Blocker+ in front of a grid, a hierarchy or Embree: whole ray-tree paths step aside.
#include <cstdint>

#include "search/blocker_cache.h"

namespace rc {

/// Blocker+ (or blocker+dir) in front of a cheap complete search. There a search makes a
/// handful of tests, and a cache answer pays only where its object and list are short and
/// met again. Each path's entry counts, over windows of kWindow lookups, how many were
/// answered without a search; where fewer than half were, the path steps aside: its next
/// kRays rays search at once, with no list looked up or built. A window failed again
/// doubles that, up to kDoublings times; a window that pays starts over.
///
/// A path stepping aside costs a counter and the search (the lookup stays small: its
/// rarer work is out of line).
class AsideBlockerCache final : public BlockerCache {
public:
    using BlockerCache::BlockerCache;
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override;

    static constexpr std::uint16_t kWindow = 32;
    static constexpr std::uint16_t kRays = 1024;
    static constexpr std::uint8_t kDoublings = 5;

private:
    /// A lookup of a path that is not stepping aside: counts it in the path's window.
    Lookup lookupInWindow(const Query& q, CacheEntry& e, Counters& n);
};

}  // namespace rc
