#pragma once
/// \file
/// \brief The complete search: what every cache falls back on when it misses.
#include <memory>
#include <string>
#include <vector>

#include "search/query.h"

namespace rc {

/// Finds the nearest hit over the whole scene. Implementations (a linear scan now, a grid
/// or BVH later) must return exactly what the linear scan returns, ties included.
class CompleteSearch {
public:
    virtual ~CompleteSearch() = default;
    /// The nearest hit of `q`, counting every ray-object test in `n`.
    virtual Answer nearest(const Query& q, Counters& n) const = 0;
    virtual std::string name() const = 0;
    /// Objects whose bounding spheres may overlap the box [lo, hi], ascending (every object
    /// may be returned). Caches build blocker lists and cylinders of safety from these.
    virtual void objectsNear(const Vec3& lo, const Vec3& hi, std::vector<int>& out) const;
    /// Objects whose bounding spheres may come within `radius` of the segment a-b (every
    /// object may be returned; by default, those of the segment's widened box).
    virtual void objectsNearSegment(const Vec3& a, const Vec3& b, double radius, std::vector<int>& out) const;
    /// Cylinders of safety are capped at this radius, so that objectsNear() of a segment's
    /// box widened by it is enough to build them (infinite: no cap, all objects).
    virtual double nearRadius() const { return kNoHit; }

protected:
    explicit CompleteSearch(const Scene& scene) : scene_(scene) {}
    const Scene& scene_;
};

/// Tests every object in the scene: the paper's "standard ray-tracing algorithm".
class LinearSearch final : public CompleteSearch {
public:
    explicit LinearSearch(const Scene& scene) : CompleteSearch(scene) {}
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "linear"; }
};

}  // namespace rc
