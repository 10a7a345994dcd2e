#pragma once
/// \file
/// \brief The Speer-DeRose-Barsky cache: the last object hit and a cylinder of safety.
#include "search/cache_strategy.h"
#include "search/cylinder_of_safety.h"

namespace rc {

/// Speer, DeRose and Barsky (1985): the cache holds the last object hit and the
/// largest capsule around the last ray segment that no other surface enters. A ray
/// hits the cache when it hits the same object and its own segment stays inside the
/// capsule; rays that hit nothing are cached the same way, their segment ending where
/// they leave the scene's bounding sphere.
class CylinderCache final : public CacheStrategy {
public:
    CylinderCache(const Scene& scene, const CompleteSearch& search)
        : CacheStrategy(scene, search), cylinders_(scene, search) {}
    CacheKind kind() const override { return CacheKind::Cylinder; }
    Lookup lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) override;

protected:
    void reload(const Query& q, const Answer& a, CacheEntry& e, Counters& n) override;

private:
    CylinderOfSafety cylinders_;
};

}  // namespace rc
