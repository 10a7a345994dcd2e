#include "search/sphere_batch.h"

#include "search/four_spheres.h"

namespace rc {

void SphereBatch::add(const Scene& scene, int id) {
    const Object& o = scene.objects[id];
    const bool sphere = o.shape == Shape::Sphere;
    // The very sphere Scene::intersect() tests, so both compute the same discriminant
    const Sphere s = sphere ? scene.spheres[o.index] : o.bound;
    ids_.push_back(id);
    x_.push_back(s.c.x);
    y_.push_back(s.c.y);
    z_.push_back(s.c.z);
    radius2_.push_back(sphere ? s.r * s.r : -1.0);
}

#ifdef RC_FOUR_SPHERES_AVX2
namespace {
/// SphereBatch::test() on the first objects, four at a time; returns how many it tested
/// (a multiple of four), leaving the rest to test()
__attribute__((target("avx2"))) std::size_t testFours(const Scene& scene, const Query& q, const int* ids,
                                                      const double* x, const double* y, const double* z,
                                                      const double* r2, std::size_t size, Answer& best,
                                                      Counters& n) {
    const RayFour ray = rayFour(q.ray.o, q.ray.d);
    const __m128i origin = _mm_set1_epi32(q.origin.object);
    const std::size_t whole = size / 4 * 4;
    std::size_t i = 0;
    while (i < whole) {
        // [scan-four]
        // Four verdicts at once; groups of four plain spheres, all clearly missed, are four
        // tests counted each and nothing else (the common case: a ray misses most objects).
        // This inner loop calls nothing, so the ray stays in registers from group to group
        const std::size_t from = i;
        int rejected = 0;
        for (; i < whole; i += 4) {
            const __m256d cx = _mm256_loadu_pd(x + i), cy = _mm256_loadu_pd(y + i);
            const __m256d cz = _mm256_loadu_pd(z + i), radius2 = _mm256_loadu_pd(r2 + i);
            rejected = clearlyMissesFour(ray, cx, cy, cz, radius2);
            if (rejected != 0xF || notPlainFour(radius2, ids + i, origin) != 0) break;
        }
        n.intersectionTests += i - from;
        if (i == whole) break;
        // [scan-four]
        // Else each of the four as test() takes it, with the verdict already computed
        for (std::size_t j = 0; j < 4; ++j) testRejected(scene, q, ids[i + j], r2[i + j], rejected >> j & 1, best, n);
        i += 4;
    }
    return whole;
}
}  // namespace
#endif

void SphereBatch::testAll(const Scene& scene, const Query& q, Answer& best, Counters& n) const {
    std::size_t tested = 0;
#ifdef RC_FOUR_SPHERES_AVX2
    if (fourSpheresAvailable())
        tested = testFours(scene, q, ids_.data(), x_.data(), y_.data(), z_.data(), radius2_.data(), ids_.size(),
                           best, n);
#endif
    test(scene, q, tested, ids_.size(), best, n);
}

}  // namespace rc
