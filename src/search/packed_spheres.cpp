#include "search/packed_spheres.h"

#include <algorithm>

#include "search/four_spheres.h"

namespace rc {

namespace {
#ifdef RC_FOUR_SPHERES_AVX2
/// A list four spheres at a time (clearlyMissesFour()) while four are left and within
/// reach; returns where the scalar loop takes over: at the last one to three, or at the
/// end when an object out of reach has ended the list
__attribute__((target("avx2"))) std::size_t testFour(const Scene& scene, const Query& q,
                                                     const PackedSpheres::Packed* all, const int* ids,
                                                     const double* reach, std::size_t size, Answer& best,
                                                     Counters& n) {
    const RayFour ray = rayFour(q.ray.o, q.ray.d);
    const __m128i origin = _mm_set1_epi32(q.origin.object);
    std::size_t i = 0;
    while (i + 4 <= size) {
        // The nearest hit known changes only when an object is tested in full, below
        const double limit = std::min(best.t, q.tmax);
        const std::size_t from = i;
        int rejected = 0;
        bool beyond = false;
        // Groups of four rejected at once, with no call: the ray stays in registers
        for (; i + 4 <= size; i += 4) {
            if (reach && !(reach[i] <= limit)) {
                beyond = true;
                break;
            }
            // [packed-four]
            // Four spheres, one load each, turned into four registers of x, y, z and r^2
            const __m256d a = _mm256_load_pd(&all[ids[i]].x);
            const __m256d b = _mm256_load_pd(&all[ids[i + 1]].x);
            const __m256d c = _mm256_load_pd(&all[ids[i + 2]].x);
            const __m256d e = _mm256_load_pd(&all[ids[i + 3]].x);
            const __m256d ab0 = _mm256_unpacklo_pd(a, b), ab1 = _mm256_unpackhi_pd(a, b);
            const __m256d ce0 = _mm256_unpacklo_pd(c, e), ce1 = _mm256_unpackhi_pd(c, e);
            const __m256d cx = _mm256_permute2f128_pd(ab0, ce0, 0x20);
            const __m256d cy = _mm256_permute2f128_pd(ab1, ce1, 0x20);
            const __m256d cz = _mm256_permute2f128_pd(ab0, ce0, 0x31);
            const __m256d r2 = _mm256_permute2f128_pd(ab1, ce1, 0x31);
            // [packed-four]
            rejected = clearlyMissesFour(ray, cx, cy, cz, r2);
            // [packed-four-all]
            // All four plain spheres, all rejected, all within reach: on to the next group (the
            // four tests are counted when this loop stops); any other group is tested one by one
            const bool allWithin = !reach || reach[i + 3] <= limit;
            if (rejected != 0xF || notPlainFour(r2, ids + i, origin) != 0 || !allWithin) break;
            // [packed-four-all]
        }
        n.intersectionTests += i - from;
        if (beyond) return size;
        if (i + 4 > size) break;
        for (std::size_t j = 0; j < 4; ++j) {
            if (reach && !(reach[i + j] <= std::min(best.t, q.tmax))) return size;
            testRejected(scene, q, ids[i + j], all[ids[i + j]].r2, rejected >> j & 1, best, n);
        }
        i += 4;
    }
    return i;
}
#endif
}  // namespace

PackedSpheres::PackedSpheres(const Scene& scene) {
    spheres_.resize(scene.objects.size(), Packed{0.0, 0.0, 0.0, -1.0});
    for (std::size_t id = 0; id < scene.objects.size(); ++id) {
        const Object& obj = scene.objects[id];
        if (obj.shape != Shape::Sphere) continue;
        const Sphere& s = scene.spheres[std::size_t(obj.index)];
        spheres_[id] = {s.c.x, s.c.y, s.c.z, s.r * s.r};
    }
}

bool PackedSpheres::simd() {
#ifdef RC_FOUR_SPHERES_AVX2
    return fourSpheresAvailable();
#else
    return false;
#endif
}

void PackedSpheres::testLong(const Scene& scene, const Query& q, const int* ids, const double* reach,
                             std::size_t size, Answer& best, Counters& n) const {
#ifdef RC_FOUR_SPHERES_AVX2
    if (simd()) {
        const std::size_t done = testFour(scene, q, spheres_.data(), ids, reach, size, best, n);
        testNearestFirstScalar(scene, q, ids + done, reach ? reach + done : nullptr, size - done, best, n);
        return;
    }
#endif
    testNearestFirstScalar(scene, q, ids, reach, size, best, n);
}

}  // namespace rc
