#pragma once
/// \file
/// \brief The complete search: what every cache falls back on when it misses.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "search/query.h"
#include "search/sphere_batch.h"

namespace rc {

/// A question about the objects' bounding spheres that every complete search can answer:
/// which objects meet a region (a blocker hull, a capsule, a cone of directions)? The
/// question measures how far a sphere lies from the region, and an object meets it when
/// its bounding sphere lies within `limit`. The measure must be a lower bound for every
/// sphere inside the one measured, so a hierarchy may skip everything under a bounding
/// sphere beyond the limit, and open the nearest first. The limit may shrink as objects
/// are found (a cylinder of safety narrows with each one).
class SphereCull {
public:
    virtual ~SphereCull() = default;
    /// How far sphere `s`, or any sphere inside it, lies from the region (at least).
    virtual double distance(const Sphere& s) = 0;
    /// Object `id`, whose bounding sphere lies at `distance` <= limit. May lower the limit.
    virtual void found(int id, double distance) = 0;
    double limit = 0.0;
    /// A hint for searches that cannot descend by spheres (a grid): every object that meets
    /// lies within `radius` of the segment a-b (infinite: anywhere).
    Vec3 a{0.0}, b{0.0};
    double radius = kNoHit;
};

/// How near segment a-b comes to a sphere (less its radius: a lower bound for any sphere
/// inside), every object but two kept under the limit: a cylinder of safety's radius. It
/// is `final`, so a traversal that knows its type calls it directly, without a virtual
/// call per sphere (CompleteSearch::clearance).
struct SegmentClearance final : SphereCull {
    /// `stopBelow`: once an object lies nearer than this, stop; `least` is then its distance
    SegmentClearance(const Vec3& from, const Vec3& to, int skip, int skipToo, double cap, double stopBelow)
        : ab(to - from), skip(skip), skipToo(skipToo), stopBelow(stopBelow), least(cap) {
        a = from;
        b = to;
        const double len2 = glm::dot(ab, ab);
        invLen2 = len2 > 0.0 ? 1.0 / len2 : 0.0;
        radius = limit = cap;
    }
    double distance(const Sphere& s) override {
        const Vec3 p = s.c - a;
        const double t = std::clamp(glm::dot(p, ab) * invLen2, 0.0, 1.0);
        return glm::length(p - t * ab) - s.r;
    }
    void found(int id, double d) override {
        if (id == skip || id == skipToo || !(d < least)) return;
        least = d;
        nearest = id;
        // Below the stop, the search is over: nothing more can meet the limit
        limit = least < stopBelow ? -kNoHit : least;
    }
    Vec3 ab;
    double invLen2;
    int skip, skipToo;
    double stopBelow;
    double least;      ///< the clearance so far (at most the cap)
    int nearest = -1;  ///< the object at that distance (-1: none nearer than the cap)
};

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

class BoundingVolumeHierarchy;

/// Tests every object in the scene: the paper's "standard ray-tracing algorithm".
///
/// Rays only. The caches' region queries (which objects meet a blocker hull, a cylinder
/// of safety, an empty cone) are the caches' own bookkeeping, not a search for a ray: they
/// go through a hierarchy of bounding spheres built once per scene, so a cache builds a
/// list or a cylinder without measuring every object. (RayCache's choice: the paper does not
/// say how lists are found. `Regions::Scan` measures every object instead.)
class LinearSearch final : public CompleteSearch {
public:
    /// How region queries (cull(), clearance()) are answered.
    enum class Regions { Hierarchy, Scan };
    explicit LinearSearch(const Scene& scene, Regions regions = Regions::Hierarchy);
    ~LinearSearch() override;
    Answer nearest(const Query& q, Counters& n) const override;
    void cull(SphereCull& c) const override;
    double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                     double stopBelow = -kNoHit, int* nearest = nullptr) const override;
    std::string name() const override { return "linear"; }
    bool cheap() const override { return false; }

private:
    SphereBatch all_;  ///< every object, in id order
    /// The bounding spheres of the objects, for region queries (none: scan them all)
    std::unique_ptr<const BoundingVolumeHierarchy> regions_;
};

}  // namespace rc
