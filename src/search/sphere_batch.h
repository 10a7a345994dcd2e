#pragma once
/// \file
/// \brief Objects stored for the complete search's inner loop: sphere centres and squared
/// radii in arrays of their own (structure of arrays), so a run of tests is one tight
/// loop with no lookup through the scene and no call for the common case, a miss.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "search/query.h"

namespace rc {

/// Does the ray (o, d) clearly miss the sphere centred at (cx, cy, cz) with squared radius
/// r2? Its stable discriminant, as sphereRootsStable() computes it, is negative by more than
/// a margin of rounding, which absorbs any difference in how the compiler fused this
/// arithmetic and the full test's. A sphere it does not reject may still be missed.
inline bool clearlyMisses(const Vec3& o, const Vec3& d, double cx, double cy, double cz, double r2) {
    const double fx = o.x - cx, fy = o.y - cy, fz = o.z - cz;
    const double b = fx * d.x + fy * d.y + fz * d.z;
    const double lx = fx - b * d.x, ly = fy - b * d.y, lz = fz - b * d.z;
    const double disc = r2 - (lx * lx + ly * ly + lz * lz);
    return disc < -1e-12 * (fx * fx + fy * fy + fz * fz + r2);
}

/// testObject() with the quick rejection of a sphere the ray clearly misses: the same
/// answers and counts, for lists tested one object at a time.
inline void testObjectQuickly(const Scene& scene, const Query& q, int id, Answer& best, Counters& n) {
    const Object& obj = scene.objects[id];
    if (obj.shape != Shape::Sphere || id == q.origin.object) {
        testObject(scene, q, id, best, n);
        return;
    }
    ++n.intersectionTests;
    const Sphere& s = scene.spheres[obj.index];
    if (clearlyMisses(q.ray.o, q.ray.d, s.c.x, s.c.y, s.c.z, s.r * s.r)) return;
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && nearer(t, id, best)) best = {id, t};
}

/// A run of objects to test against rays. Spheres are rejected in the loop when their
/// discriminant is clearly negative; everything else (a possible hit, a polygon, the
/// ray's own origin object) goes through testObject(), so the answers and the counts are
/// exactly those of a plain loop over testObject().
class SphereBatch {
public:
    /// Appends object `id` of `scene`.
    void add(const Scene& scene, int id);
    std::size_t size() const { return ids_.size(); }

    /// Tests objects [begin, end) against `q`, keeping the nearest in `best`.
    void test(const Scene& scene, const Query& q, std::size_t begin, std::size_t end, Answer& best,
              Counters& n) const {
        // [sphere-batch]
        const Vec3 o = q.ray.o, d = q.ray.d;
        for (std::size_t i = begin; i < end; ++i) {
            const int id = ids_[i];
            if (radius2_[i] < 0.0 || id == q.origin.object) {
                testObject(scene, q, id, best, n);  // a polygon, a cone, or the surface the ray leaves
                continue;
            }
            // The stable discriminant clearly negative: a miss
            ++n.intersectionTests;
            if (clearlyMisses(o, d, x_[i], y_[i], z_[i], radius2_[i])) continue;
            const double t = scene.intersect(q.ray, id, q.origin);
            if (t < q.tmax && nearer(t, id, best)) best = {id, t};
        }
        // [sphere-batch]
    }

private:
    std::vector<int> ids_;
    std::vector<double> x_, y_, z_;
    std::vector<double> radius2_;  ///< r * r; negative for a polygon or a cone
};

}  // namespace rc
