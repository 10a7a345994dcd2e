#include "search/clearance_scan.h"

#include <algorithm>
#include <cmath>

#include "geometry/safety_cylinder.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RC_CLEARANCE_AVX2 1
#include <immintrin.h>
#endif

namespace rc {

ClearanceScan::ClearanceScan(const Scene& scene) : size_(scene.objects.size()) {
    // Padded to four: a pad's radius is -infinity, so it lies infinitely far from anything
    const std::size_t padded = (size_ + 3) / 4 * 4;
    x_.assign(padded, 0.0), y_.assign(padded, 0.0), z_.assign(padded, 0.0);
    r_.assign(padded, -kNoHit);
    for (std::size_t id = 0; id < size_; ++id) {
        const Sphere& s = scene.objects[id].bound;
        x_[id] = s.c.x, y_[id] = s.c.y, z_[id] = s.c.z, r_[id] = s.r;
    }
}

namespace {
// BEGIN SOLUTION 02
/// The segment's inverse squared length, as SegmentClearance keeps it (0 for a point).
double inverseLength2(const Vec3& ab) {
    const double len2 = (ab.x * ab.x + ab.y * ab.y) + ab.z * ab.z;
    return len2 > 0.0 ? 1.0 / len2 : 0.0;
}

#ifdef RC_CLEARANCE_AVX2
// [clearance-four]
// Four spheres at a time, SegmentClearance::distance() operation for operation (no fused
// multiply-add: this function's target has none), and a running least per lane kept by a
// select, not a branch
__attribute__((target("avx2"))) double clearanceFour(const double* x, const double* y, const double* z,
                                                     const double* r, std::size_t size, const Vec3& a,
                                                     const Vec3& b, int skip, int skipToo, double cap,
                                                     int* nearest) {
    const Vec3 ab = b - a;
    const __m256d ax = _mm256_set1_pd(a.x), ay = _mm256_set1_pd(a.y), az = _mm256_set1_pd(a.z);
    const __m256d bx = _mm256_set1_pd(ab.x), by = _mm256_set1_pd(ab.y), bz = _mm256_set1_pd(ab.z);
    const __m256d inv = _mm256_set1_pd(inverseLength2(ab)), zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d skip1 = _mm256_set1_pd(skip), skip2 = _mm256_set1_pd(skipToo), four = _mm256_set1_pd(4.0);
    __m256d least = _mm256_set1_pd(cap), at = _mm256_set1_pd(-1.0), id = _mm256_set_pd(3.0, 2.0, 1.0, 0.0);
    for (std::size_t i = 0; i < size; i += 4, id = _mm256_add_pd(id, four)) {
        const __m256d px = _mm256_sub_pd(_mm256_loadu_pd(x + i), ax), py = _mm256_sub_pd(_mm256_loadu_pd(y + i), ay),
                      pz = _mm256_sub_pd(_mm256_loadu_pd(z + i), az);
        // t = clamp(dot(p, ab) / |ab|^2, 0, 1): max, then min, each keeping a NaN as std::clamp does
        const __m256d dot = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(px, bx), _mm256_mul_pd(py, by)),
                                          _mm256_mul_pd(pz, bz));
        const __m256d t = _mm256_min_pd(one, _mm256_max_pd(zero, _mm256_mul_pd(dot, inv)));
        const __m256d qx = _mm256_sub_pd(px, _mm256_mul_pd(t, bx)), qy = _mm256_sub_pd(py, _mm256_mul_pd(t, by)),
                      qz = _mm256_sub_pd(pz, _mm256_mul_pd(t, bz));
        const __m256d len = _mm256_sqrt_pd(
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(qx, qx), _mm256_mul_pd(qy, qy)), _mm256_mul_pd(qz, qz)));
        const __m256d d = _mm256_sub_pd(len, _mm256_loadu_pd(r + i));
        // Nearer than the least so far, and not one of the two left out
        const __m256d out = _mm256_or_pd(_mm256_cmp_pd(id, skip1, _CMP_EQ_OQ), _mm256_cmp_pd(id, skip2, _CMP_EQ_OQ));
        const __m256d nearer = _mm256_andnot_pd(out, _mm256_cmp_pd(d, least, _CMP_LT_OQ));
        least = _mm256_blendv_pd(least, d, nearer);
        at = _mm256_blendv_pd(at, id, nearer);
    }
    // The least of the four lanes (the lowest id of a tie; a lane holds an id only below the cap)
    alignas(32) double l[4], k[4];
    _mm256_store_pd(l, least);
    _mm256_store_pd(k, at);
    int lane = 0;
    for (int j = 1; j < 4; ++j)
        if (l[j] < l[lane] || (l[j] == l[lane] && k[j] < k[lane])) lane = j;
    if (nearest) *nearest = int(k[lane]);
    return l[lane];
}
// [clearance-four]
#endif
// END SOLUTION
// BEGIN STUB
// // Tutorial 02 open: the scalar loop below measures with the student's rc::segmentDistance
// END STUB
}  // namespace

double ClearanceScan::clearanceScalar(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                                      int* nearest) const {
    // SegmentClearance::distance() and found() on every object in id order
    // BEGIN SOLUTION 02
    const Vec3 ab = b - a;
    const double inv = inverseLength2(ab);
    // END SOLUTION
    // BEGIN STUB
    // END STUB
    double least = cap;
    int at = -1;
    for (std::size_t i = 0; i < size_; ++i) {
        // BEGIN SOLUTION 02
        const double px = x_[i] - a.x, py = y_[i] - a.y, pz = z_[i] - a.z;
        const double t = std::clamp(((px * ab.x + py * ab.y) + pz * ab.z) * inv, 0.0, 1.0);
        const double qx = px - t * ab.x, qy = py - t * ab.y, qz = pz - t * ab.z;
        const double d = std::sqrt((qx * qx + qy * qy) + qz * qz) - r_[i];
        // END SOLUTION
        // BEGIN STUB
        // const double d = segmentDistance(Vec3(x_[i], y_[i], z_[i]), a, b) - r_[i];
        // END STUB
        if (int(i) == skip || int(i) == skipToo || !(d < least)) continue;
        least = d;
        at = int(i);
    }
    if (nearest) *nearest = at;
    return least;
}

double ClearanceScan::clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                                int* nearest) const {
#ifdef RC_CLEARANCE_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    // BEGIN SOLUTION 02
    if (avx2) return clearanceFour(x_.data(), y_.data(), z_.data(), r_.data(), x_.size(), a, b, skip, skipToo, cap, nearest);
    // END SOLUTION
    // BEGIN STUB
    // (void)avx2;  // tutorial 02 open: one sphere at a time, with the student's distance
    // END STUB
#endif
    return clearanceScalar(a, b, skip, skipToo, cap, nearest);
}

}  // namespace rc
