#include "search/packed_spheres.h"

#include <algorithm>

#include "search/four_spheres.h"
#ifdef RC_FOUR_SPHERES_AVX2
#define RC_PACKED_AVX2 1
#endif

namespace rc {

namespace {
#ifdef RC_PACKED_AVX2
/// Four spheres at a time: clearlyMisses() on each, in the same operations in the same
/// order (no fused multiply-add: this function's target has none), so the same bits.
__attribute__((target("avx2"))) void testFour(const Scene& scene, const Query& q, const PackedSpheres::Packed* all,
                                              const int* ids, const double* reach, std::size_t size, Answer& best,
                                              Counters& n) {
    const Vec3 o = q.ray.o, d = q.ray.d;
    const RayFour ray = rayFour(o, d);
    const __m256d zero = _mm256_setzero_pd();
    const __m128i origin = _mm_set1_epi32(q.origin.object);
    std::size_t i = 0;
    for (; i + 4 <= size; i += 4) {
        const double limit = std::min(best.t, q.tmax);
        if (reach && !(reach[i] <= limit)) return;
        // [packed-four]
        // Four spheres, one load each, turned into four registers of x, y, z and r^2
        const __m256d a = _mm256_load_pd(&all[ids[i]].x), b = _mm256_load_pd(&all[ids[i + 1]].x);
        const __m256d c = _mm256_load_pd(&all[ids[i + 2]].x), e = _mm256_load_pd(&all[ids[i + 3]].x);
        const __m256d ab0 = _mm256_unpacklo_pd(a, b), ab1 = _mm256_unpackhi_pd(a, b);
        const __m256d ce0 = _mm256_unpacklo_pd(c, e), ce1 = _mm256_unpackhi_pd(c, e);
        const __m256d cx = _mm256_permute2f128_pd(ab0, ce0, 0x20), cy = _mm256_permute2f128_pd(ab1, ce1, 0x20);
        const __m256d cz = _mm256_permute2f128_pd(ab0, ce0, 0x31), r2 = _mm256_permute2f128_pd(ab1, ce1, 0x31);
        // [packed-four]
        const int rejected = clearlyMissesFour(ray, cx, cy, cz, r2);
        // [packed-four-all]
        // All four plain spheres, all rejected, all within reach: four tests counted, nothing else
        const int notSpheres = _mm256_movemask_pd(_mm256_cmp_pd(r2, zero, _CMP_LT_OQ));
        const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ids + i));
        const int origins = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(four, origin)));
        if (rejected == 0xF && (notSpheres | origins) == 0 && (!reach || reach[i + 3] <= limit)) {
            n.intersectionTests += 4;
            continue;
        }
        // [packed-four-all]
        for (std::size_t j = 0; j < 4; ++j) {
            if (reach && !(reach[i + j] <= std::min(best.t, q.tmax))) return;
            PackedSpheres::visit(scene, q, ids[i + j], all[ids[i + j]], (rejected >> j) & 1, best, n);
        }
    }
    for (; i < size; ++i) {
        if (reach && !(reach[i] <= std::min(best.t, q.tmax))) return;
        const PackedSpheres::Packed& p = all[ids[i]];
        PackedSpheres::visit(scene, q, ids[i], p, p.r2 >= 0.0 && clearlyMisses(o, d, p.x, p.y, p.z, p.r2), best, n);
    }
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
#ifdef RC_PACKED_AVX2
    return fourSpheresAvailable();
#else
    return false;
#endif
}

void PackedSpheres::testLong(const Scene& scene, const Query& q, const int* ids, const double* reach,
                             std::size_t size, Answer& best, Counters& n) const {
#ifdef RC_PACKED_AVX2
    if (simd()) {
        testFour(scene, q, spheres_.data(), ids, reach, size, best, n);
        return;
    }
#endif
    testNearestFirstScalar(scene, q, ids, reach, size, best, n);
}

}  // namespace rc
