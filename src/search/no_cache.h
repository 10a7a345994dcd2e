#pragma once
/// \file
/// \brief No cache: every ray is a complete search.
#include "search/cache_strategy.h"

namespace rc {

/// Every ray searches the whole scene: the baseline of Table 1.
class NoCache final : public CacheStrategy {
public:
    using CacheStrategy::CacheStrategy;
    CacheKind kind() const override { return CacheKind::None; }
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override;
    bool caches() const override { return false; }

protected:
    void reload(const Query&, const Answer&, CacheEntry&, Counters&) override {}
};

}  // namespace rc
