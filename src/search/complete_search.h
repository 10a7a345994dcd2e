#pragma once
/// \file
/// \brief The complete search: what every cache falls back on when it misses. The paper's
/// own, which tests every object, is LinearSearch (search/linear_search.h).
#include <string>

#include "search/query.h"
#include "search/sphere_cull.h"

namespace rc {

/// Finds the nearest hit over the whole scene. Implementations (a linear scan, a grid, a
/// BVH) must return exactly what the linear scan returns, ties included.
class CompleteSearch {
public:
    virtual ~CompleteSearch() = default;
    /// The nearest hit of `q`, counting every ray-object test in `n`.
    virtual Answer nearest(const Query& q, Counters& n) const = 0;
    virtual std::string name() const = 0;
    /// Calls `c.found` for every object whose bounding sphere meets `c`. By default, measures
    /// every object.
    virtual void cull(SphereCull& c) const;
    /// The least distance from segment a-b to the bounding sphere of any object but `skip`
    /// and `skipToo`, at most `cap`: the radius of a cylinder of safety. Once an object
    /// nearer than `stopBelow` is found, that object's distance, an upper bound (so the
    /// result is exact whenever it is at least `stopBelow`). By default, a cull. `nearest`,
    /// if given, is set to the object at the distance returned (-1 for the cap).
    virtual double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                             double stopBelow = -kNoHit, int* nearest = nullptr) const;
    /// Cylinders of safety are capped at this radius, so that the objects near the segment
    /// (the cull's hint) are enough to build them (infinite: no cap). Where it is finite,
    /// cull() cannot find the objects near a direction cheaply, so the caches build no
    /// empty cones.
    virtual double nearRadius() const { return kNoHit; }
    /// Does a search cost a few tests rather than one per object (a grid, a hierarchy)?
    /// Then a long blocker list costs more than the search it would save.
    virtual bool cheap() const { return true; }

protected:
    explicit CompleteSearch(const Scene& scene) : scene_(scene) {}
    const Scene& scene_;
};

}  // namespace rc
