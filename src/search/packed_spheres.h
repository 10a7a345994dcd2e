#pragma once
/// \file
/// \brief Every object's sphere by id, packed for testing lists of ids: the quick rejection
/// of four spheres at a time (AVX2, picked at run time, else one at a time), with exactly
/// the answers and counts of testObjectQuickly() called on each in turn.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "search/sphere_batch.h"

namespace rc {

/// The spheres of a scene by object id, each in 32 bytes (one AVX2 register): a list of
/// potential blockers is a list of ids, and testing it one object at a time goes through
/// the scene's objects to its spheres, two loads a test. Here the four numbers the quick
/// rejection needs are one load, and four spheres are rejected at once.
class PackedSpheres {
public:
    explicit PackedSpheres(const Scene& scene);

    /// Whether this processor runs the AVX2 loop (else the scalar one does).
    static bool simd();

    /// testObjectQuickly() on ids[0, size), in order (the paper's blocker list).
    void testAll(const Scene& scene, const Query& q, const int* ids, std::size_t size, Answer& best,
                 Counters& n) const {
        testNearestFirst(scene, q, ids, nullptr, size, best, n);
    }
    /// The same on a list nearest first: stops at the first object whose `reach` exceeds
    /// min(best.t, q.tmax), as no ray can meet it before the nearest hit known. Without
    /// `reach` (nullptr), every object is tested.
    /// A list shorter than four is all tail: it is tested here, one at a time, with no call.
    void testNearestFirst(const Scene& scene, const Query& q, const int* ids, const double* reach, std::size_t size,
                          Answer& best, Counters& n) const {
        if (size < 4) {
            testNearestFirstScalar(scene, q, ids, reach, size, best, n);
            return;
        }
        testLong(scene, q, ids, reach, size, best, n);
    }
    /// The scalar loop alone, whatever the processor (for the tests and the microbenchmark).
    void testNearestFirstScalar(const Scene& scene, const Query& q, const int* ids, const double* reach,
                                std::size_t size, Answer& best, Counters& n) const {
        const Vec3 o = q.ray.o, d = q.ray.d;
        for (std::size_t i = 0; i < size; ++i) {
            if (reach && !(reach[i] <= std::min(best.t, q.tmax))) return;
            const Packed& p = spheres_[std::size_t(ids[i])];
            testRejected(scene, q, ids[i], p.r2, p.r2 >= 0.0 && clearlyMisses(o, d, p.x, p.y, p.z, p.r2), best, n);
        }
    }

    /// A sphere's centre and squared radius (negative: the object is no sphere).
    struct alignas(32) Packed {
        double x, y, z, r2;
    };

private:
    /// Four or more: four at a time where the processor can.
    void testLong(const Scene& scene, const Query& q, const int* ids, const double* reach, std::size_t size,
                  Answer& best, Counters& n) const;
    std::vector<Packed> spheres_;
};

}  // namespace rc
