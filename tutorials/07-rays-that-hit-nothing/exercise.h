#pragma once
// Tutorial 07 (open-ended): a better cache for rays that hit nothing.
#include <memory>
#include <vector>

#include "geometry/intersection.h"
#include "geometry/sphere.h"
#include "search/query.h"  // rc::Answer, rc::nearer

namespace tutorial {

// [declaration-basic]
/// Part 1 (basic). The half-angle, in radians, of the widest cone of directions around
/// the unit vector `axis`, with its apex at `apex`, whose rays meet none of `spheres`.
/// Seen from the apex, sphere j covers the directions within asin(r_j / |c_j - apex|) of
/// the direction to its centre, so the cone may open until it touches the nearest such
/// disc of directions. Negative when the ray along `axis` meets a sphere, or when the
/// apex is inside one; rc::kNoHit (infinity) when there are no spheres.
double emptyConeAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres);
// [declaration-basic]

// [declaration-cache]
/// The scene as your cache sees it: only through the check, which counts every question.
/// Each call of distance() or disc() is one test of one sphere, whichever of your
/// functions makes it (the cache's constructor, lookup() or searched()), and every n tests
/// (n = size()) count as one more complete search. The spheres themselves are not handed
/// out. Everything is seen from one point, the eye.
class Spheres {
public:
    /// Sphere j as the eye sees it: a disc of directions.
    struct Disc {
        /// Radians between the axis asked about and the direction to sphere j's centre.
        double centreAngle;
        /// The disc's angular radius, asin(r_j / |c_j - eye|) (pi: the eye is inside).
        double radius;
    };
    virtual ~Spheres() = default;
    /// The number of spheres, n. Free.
    virtual int size() const = 0;
    /// One test: how far the eye ray with unit direction `d` travels to meet sphere j
    /// first, rc::kNoHit when it misses.
    virtual double distance(const rc::Vec3& d, int j) const = 0;
    /// One test: sphere j's disc of directions, measured from the unit vector `axis`.
    virtual Disc disc(const rc::Vec3& axis, int j) const = 0;
};

/// What a cache knows about a ray without a complete search.
struct Known {
    bool answered = false;  ///< false: the cache cannot tell, the ray gets a complete search
    int object = -1;        ///< when answered: the sphere the ray hits first, -1 for nothing
};

/// Parts 2 and 3 (intermediate, challenge). A cache for the eye rays of one image, asked
/// in scanline order. The check asks lookup() for every ray; when it is not answered, the
/// check makes a complete search (n tests, not charged to your cache) and tells the cache
/// the result with searched(). An answer must be exact: the sphere the complete search
/// would find (equal distances: the lower index), or -1 when the ray hits nothing. A
/// lookup that makes n tests or more is a complete search under another name: the check
/// counts it as one, not as an answer.
class NothingCache {
public:
    virtual ~NothingCache() = default;
    /// Answer the eye ray with unit direction `d`, or say you cannot.
    virtual Known lookup(const rc::Vec3& d) = 0;
    /// After a complete search: the eye ray with direction `d` hits sphere `object`
    /// first (-1: nothing).
    virtual void searched(const rc::Vec3& d, int object) = 0;
};

/// Your cache for the eye rays of a scene; `spheres` outlives it.
std::unique_ptr<NothingCache> makeNothingCache(const Spheres& spheres);
// [declaration-cache]

}  // namespace tutorial
