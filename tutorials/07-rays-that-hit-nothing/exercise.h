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
/// What a cache knows about a ray without a complete search.
struct Known {
    bool answered = false;  ///< false: the cache cannot tell, the ray gets a complete search
    int object = -1;        ///< when answered: the sphere the ray hits first, -1 for nothing
};

/// Parts 2 and 3 (intermediate, challenge). A cache for the eye rays of one image, all
/// from the point `eye`, asked in scanline order. The check asks lookup() for every
/// ray; when it is not answered, the check makes a complete search (one test per sphere)
/// and tells the cache the result with searched(). An answer must be exact: the sphere
/// the complete search would find (equal distances: the lower index), or -1 when the
/// ray hits nothing. Count, in `tests`, every ray-sphere test your lookup makes.
class NothingCache {
public:
    virtual ~NothingCache() = default;
    /// Answer the eye ray with unit direction `d`, or say you cannot.
    virtual Known lookup(const rc::Vec3& d, long& tests) = 0;
    /// After a complete search: the eye ray with direction `d` hits sphere `object`
    /// first (-1: nothing).
    virtual void searched(const rc::Vec3& d, int object) = 0;
};

/// Your cache for the eye rays from `eye` in a scene of `spheres`.
std::unique_ptr<NothingCache> makeNothingCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye);
// [declaration-cache]

}  // namespace tutorial
