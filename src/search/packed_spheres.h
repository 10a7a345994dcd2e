#pragma once
/// \file
/// \brief Every object's sphere by id, packed for testing lists of ids: the quick rejection
/// of four spheres at a time (AVX2, picked at run time, else one at a time), with exactly
/// the answers and counts of testObjectQuickly() called on each in turn.
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
    void testNearestFirst(const Scene& scene, const Query& q, const int* ids, const double* reach, std::size_t size,
                          Answer& best, Counters& n) const;
    /// The scalar loop alone, whatever the processor (for the tests and the microbenchmark).
    void testNearestFirstScalar(const Scene& scene, const Query& q, const int* ids, const double* reach,
                                std::size_t size, Answer& best, Counters& n) const;

    /// A sphere's centre and squared radius (negative: the object is no sphere).
    struct alignas(32) Packed {
        double x, y, z, r2;
    };

private:
    std::vector<Packed> spheres_;
};

}  // namespace rc
