#pragma once
/// \file
/// \brief Objects stored for the complete search's inner loop: sphere centres and squared
/// radii in arrays of their own (structure of arrays), so a run of tests is one tight
/// loop with no lookup through the scene and no call for the common case, a miss.
#include <cstddef>
#include <vector>

#include "search/object_test.h"

namespace rc {

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
            keepNearer(scene, q, id, best);
        }
        // [sphere-batch]
    }

    /// test() on every object, four at a time where the processor can (AVX2): the same
    /// answers and counts, and no call for a group the ray clearly misses whole.
    void testAll(const Scene& scene, const Query& q, Answer& best, Counters& n) const;

private:
    std::vector<int> ids_;
    std::vector<double> x_, y_, z_;
    std::vector<double> radius2_;  ///< r * r; negative for a polygon or a cone
};

}  // namespace rc
