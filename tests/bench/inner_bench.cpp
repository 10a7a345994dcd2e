// Catch2 benchmarks of the inner routines: the sphere test, the hull test, capsule
// containment, a cached lookup against a complete search.
//   build/tests/raycache_microbench            (all)
//   build/tests/raycache_microbench "[sphere]" (one group)
#define CATCH_CONFIG_MAIN
#define CATCH_CONFIG_ENABLE_BENCHMARKING
#include <catch2/catch.hpp>


#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/intersection.h"
#include "geometry/safety_cylinder.h"
#include "scene/builtin_scenes.h"
#include "search/accelerator.h"
#include "search/cache_strategy.h"
#include "../uniform.h"

using namespace rc;

namespace {
std::vector<Ray> randomRays(int n, std::uint64_t seed) {
    Random rng(seed);
    const Uniform g{-1.0, 1.0};
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i)
        rays.push_back({Vec3(g(rng), g(rng), 5.0 + g(rng)), glm::normalize(Vec3(0.3 * g(rng), 0.3 * g(rng), -1.0))});
    return rays;
}
}  // namespace

TEST_CASE("sphere intersection", "[sphere]") {
    const std::vector<Ray> rays = randomRays(1024, 1);
    const Sphere s{Vec3(0.1, -0.2, 0.0), 0.8};
    BENCHMARK("stable roots x1024") {
        double sum = 0;
        for (const Ray& r : rays) sum += sphereRootsStable(r, s).t0;
        return sum;
    };
    BENCHMARK("textbook roots x1024") {
        double sum = 0;
        for (const Ray& r : rays) sum += sphereRootsTextbook(r, s).t0;
        return sum;
    };
}

TEST_CASE("hull and capsule tests", "[hull]") {
    Random rng(2);
    const Uniform u{-3, 3};
    std::vector<Vec3> points;
    for (int i = 0; i < 1024; ++i) points.emplace_back(u(rng), u(rng), u(rng));
    const Sphere a{Vec3(-1, 0, 0), 1.0}, b{Vec3(2, 0.5, 0), 0.3};
    const SafetyCylinder cyl{Vec3(-1, 0, 0), Vec3(2, 0.5, 0), 0.4};
    BENCHMARK("hull distance x1024") {
        double sum = 0;
        for (const Vec3& p : points) sum += hullDistance(p, a, b);
        return sum;
    };
    BENCHMARK("capsule distance x1024") {
        double sum = 0;
        for (const Vec3& p : points) sum += cyl.distance(p);
        return sum;
    };
}

TEST_CASE("complete search against a cached lookup", "[search]") {
    const Scene scene = makeBuiltin("cube:10");
    const std::vector<Ray> rays = randomRays(256, 3);
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
        auto search = makeCompleteSearch(accel, scene);
        BENCHMARK(std::string(toString(accel)) + " complete search x256") {
            Counters n;
            int hits = 0;
            for (const Ray& r : rays) hits += search->nearest({r, kNoHit, {}, RayKind::Primary, -1}, n).object >= 0;
            return hits;
        };
    }
    auto linear = makeCompleteSearch(AccelKind::Linear, scene);
    auto blocker = makeStrategy(CacheKind::Blocker, scene, *linear);
    const Ray centre{scene.camera.from, glm::normalize(scene.camera.at - scene.camera.from)};
    CacheEntry entry;
    Counters warm;
    blocker->lookup({centre, kNoHit, {}, RayKind::Primary, -1}, entry, LookupMode::Full, warm);
    BENCHMARK("blocker cache hit x256 (the same eye ray)") {
        Counters n;
        int hits = 0;
        for (int i = 0; i < 256; ++i)
            hits += blocker->lookup({centre, kNoHit, {}, RayKind::Primary, -1}, entry, LookupMode::CheapOnly, n).known;
        return hits;
    };
}
