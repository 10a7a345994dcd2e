#pragma once
/// \file
/// \brief rc::clearlyMisses() on four spheres at once with AVX2: the quick rejection shared
/// by the complete search's scan (SphereBatch::testAll) and the lists' tests (PackedSpheres).
///
/// A ray misses most objects, so most of a scan's tests are this rejection: four of them
/// computed at once, and groups rejected whole stepped over by a loop that calls nothing,
/// make a test a quarter to a third of its scalar cost (`raycache table1` prints a test's
/// cost as "an object test"). Both users test through it, so the uncached scan rejects
/// spheres the way the caches' lists do. It answers a tutorial (06), so this header holds a
/// solution region: only the sources that test objects include it.
#include "search/object_test.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RC_FOUR_SPHERES_AVX2 1
#include <immintrin.h>

namespace rc {

/// Whether this processor has AVX2, which the functions below need: asked once, at run time.
inline bool fourSpheresAvailable() {
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return avx2;
}

/// A ray's origin and direction, each coordinate in all four lanes.
struct RayFour {
    __m256d ox, oy, oz, dx, dy, dz;
};

__attribute__((target("avx2"))) inline RayFour rayFour(const Vec3& o, const Vec3& d) {
    return {_mm256_set1_pd(o.x), _mm256_set1_pd(o.y), _mm256_set1_pd(o.z),
            _mm256_set1_pd(d.x), _mm256_set1_pd(d.y), _mm256_set1_pd(d.z)};
}

/// Bit k is set when the ray clearly misses sphere k (centre cx, cy, cz, squared radius r2):
/// clearlyMisses() on each, in the same operations in the same order (no fused multiply-add:
/// this function's target has none), so the same bits.
__attribute__((target("avx2"))) inline int clearlyMissesFour(const RayFour& ray, __m256d cx, __m256d cy,
                                                             __m256d cz, __m256d r2) {
    // BEGIN SOLUTION 06
    // clearlyMisses(), operation for operation
    const __m256d margin = _mm256_set1_pd(-1e-12);
    const __m256d fx = _mm256_sub_pd(ray.ox, cx), fy = _mm256_sub_pd(ray.oy, cy), fz = _mm256_sub_pd(ray.oz, cz);
    const __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, ray.dx), _mm256_mul_pd(fy, ray.dy)),
                                    _mm256_mul_pd(fz, ray.dz));
    const __m256d lx = _mm256_sub_pd(fx, _mm256_mul_pd(b, ray.dx)), ly = _mm256_sub_pd(fy, _mm256_mul_pd(b, ray.dy)),
                  lz = _mm256_sub_pd(fz, _mm256_mul_pd(b, ray.dz));
    const __m256d disc = _mm256_sub_pd(
        r2, _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(lx, lx), _mm256_mul_pd(ly, ly)), _mm256_mul_pd(lz, lz)));
    const __m256d scale = _mm256_add_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, fx), _mm256_mul_pd(fy, fy)), _mm256_mul_pd(fz, fz)), r2);
    return _mm256_movemask_pd(_mm256_cmp_pd(disc, _mm256_mul_pd(margin, scale), _CMP_LT_OQ));
    // END SOLUTION
    // BEGIN STUB
    // // Tutorial 06 is open: clearlyMisses() rejects nothing, and neither does this
    // (void)ray, (void)cx, (void)cy, (void)cz, (void)r2;
    // return 0;
    // END STUB
}

/// Bit k is set when object k of four (ids[0..3], squared radii r2) may not be a plain
/// sphere whose rejection decides it: no sphere (r2 negative: its sign bit is read) or the
/// ray's own object (`origin`, its id in all four lanes). A group with no bit set and all
/// four rejected is four tests and nothing else; any other goes one object at a time
/// through testRejected(), which decides exactly.
__attribute__((target("avx2"))) inline int notPlainFour(__m256d r2, const int* ids, __m128i origin) {
    const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ids));
    return _mm256_movemask_pd(r2) | _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(four, origin)));
}

}  // namespace rc
#endif
