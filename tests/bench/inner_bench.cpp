// Catch2 benchmarks of the inner routines: the sphere test, the hull test, capsule
// containment, a cached lookup against a complete search.
//   build/tests/raycache_microbench            (all)
//   build/tests/raycache_microbench "[sphere]" (one group)
#define CATCH_CONFIG_MAIN
#define CATCH_CONFIG_ENABLE_BENCHMARKING
#include <catch2/catch.hpp>

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <unordered_map>
#include <vector>


#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/intersection.h"
#include "geometry/safety_cylinder.h"
#include "scene/builtin_scenes.h"
#include "search/accelerator.h"
#include "search/bounding_volume_hierarchy.h"
#include "search/cache_strategy.h"
#include "search/clearance_scan.h"
#include "search/direction_lists.h"
#include "search/linear_search.h"
#include "search/list_table.h"
#include "search/packed_spheres.h"
#include "search/sphere_batch.h"
#include "view/block_vector.h"
#include "view/event_record.h"
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

/// Runs test(q, best, n) on a query for each of `rays`; returns what the answers and
/// counts add up to, so that no benchmark's work is optimized away
template <class Test>
int testRays(const std::vector<Ray>& rays, Test test) {
    Counters n;
    int found = 0;
    for (const Ray& r : rays) {
        Query q;
        q.ray = r;
        Answer best;
        test(q, best, n);
        found += best.object;
    }
    return found + int(n.intersectionTests);
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

TEST_CASE("the radius of a cylinder of safety: the hierarchy against the scan", "[clearance]") {
    // Segments from the eye and from objects to points across the scene, as the caches'
    // rays that hit nothing leave them; the same radius either way
    for (const char* spec : {"cube:5", "cube:8", "cube:10"}) {
        const Scene scene = makeBuiltin(spec);
        const BoundingVolumeHierarchy bvh(scene);
        const ClearanceScan scan(scene);
        Random rng(7);
        const Uniform u{-1.0, 1.0};
        std::vector<std::pair<Vec3, Vec3>> segments;
        for (int i = 0; i < 256; ++i) {
            const Vec3 from = i % 2 ? scene.camera.from : scene.objects[std::size_t(i) % scene.objects.size()].bound.c;
            segments.emplace_back(from, scene.bound.c + scene.bound.r * Vec3(u(rng), u(rng), u(rng)));
        }
        for (const auto& [a, b] : segments) REQUIRE(bvh.clearance(a, b, -1, -1, kNoHit) == scan.clearance(a, b, -1, -1, kNoHit, nullptr));
        BENCHMARK(std::string(spec) + ": through the hierarchy x256") {
            double sum = 0;
            for (const auto& [a, b] : segments) sum += bvh.clearance(a, b, -1, -1, kNoHit);
            return sum;
        };
        BENCHMARK(std::string(spec) + ": every sphere, four at a time x256") {
            double sum = 0;
            for (const auto& [a, b] : segments) sum += scan.clearance(a, b, -1, -1, kNoHit, nullptr);
            return sum;
        };
    }
}

// The hand-written containers against the standard library's: the trace recorder's
// BlockVector against std::deque and std::vector (appending a render's events, reading them
// back, and the heap each holds), the blocker lists' ListTable against std::unordered_map.
namespace {
constexpr std::size_t kEvents = std::size_t(1) << 20;

/// Heap bytes in use, mapped blocks included (glibc).
std::size_t heapInUse() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

/// The most heap a container holds while 1.5 x 2^20 events are appended to it (a count
/// that is no power of two, as a render's is not).
constexpr std::size_t kHeld = 3 * (std::size_t(1) << 19);
template <class Container>
std::size_t heldBytes() {
    const std::size_t before = heapInUse();
    std::size_t most = 0;
    auto* c = new Container;
    for (std::size_t i = 0; i < kHeld; ++i) {
        c->push_back(EventRecord{});
        if ((i & 1023) == 0 || i + 1 == kHeld) most = std::max(most, heapInUse() - before);
    }
    delete c;
    return most;
}
}  // namespace

TEST_CASE("containers: BlockVector against std::deque and std::vector", "[containers]") {
    std::printf("most heap held while appending %zu events of %zu bytes: BlockVector %zu, std::deque %zu, std::vector %zu\n", kHeld,
                sizeof(EventRecord), heldBytes<BlockVector<EventRecord>>(), heldBytes<std::deque<EventRecord>>(),
                heldBytes<std::vector<EventRecord>>());
    EventRecord e;
    BENCHMARK("BlockVector: append 2^20 events") {
        BlockVector<EventRecord> v;
        for (std::size_t i = 0; i < kEvents; ++i) {
            e.step = int(i);
            v.push_back(e);
        }
        return v.size();
    };
    BENCHMARK("std::deque: append 2^20 events") {
        std::deque<EventRecord> v;
        for (std::size_t i = 0; i < kEvents; ++i) {
            e.step = int(i);
            v.push_back(e);
        }
        return v.size();
    };
    BENCHMARK("std::vector: append 2^20 events") {
        std::vector<EventRecord> v;
        for (std::size_t i = 0; i < kEvents; ++i) {
            e.step = int(i);
            v.push_back(e);
        }
        return v.size();
    };
    BlockVector<EventRecord> blocks;
    std::deque<EventRecord> deque;
    for (std::size_t i = 0; i < kEvents; ++i) {
        e.step = int(i);
        blocks.push_back(e);
        deque.push_back(e);
    }
    // Random reads, as the GUI reads a pixel's events back
    std::vector<std::size_t> at(4096);
    Random rng(7);
    for (std::size_t& i : at) i = std::size_t(rng() * double(kEvents));
    BENCHMARK("BlockVector: 4096 random reads") {
        std::int64_t s = 0;
        for (std::size_t i : at) s += blocks[i].step;
        return s;
    };
    BENCHMARK("std::deque: 4096 random reads") {
        std::int64_t s = 0;
        for (std::size_t i : at) s += deque[i].step;
        return s;
    };
}

TEST_CASE("containers: ListTable against std::unordered_map", "[containers]") {
    // Keys as the blocker lists make them: a pair of sites packed in 64 bits
    constexpr std::uint32_t kKeys = 1u << 16;
    std::vector<std::uint64_t> keys(kKeys);
    Random rng(11);
    for (std::uint64_t& k : keys) k = (std::uint64_t(rng() * 1e5) << 32) | std::uint64_t(rng() * 1e5);
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    ListTable table;
    std::unordered_map<std::uint64_t, std::uint32_t> map;
    for (std::uint32_t i = 0; i < keys.size(); ++i) {
        table.insert(keys[i], i);
        map.emplace(keys[i], i);
    }
    // Lookups as rays make them: half of them kept, half not
    std::vector<std::uint64_t> asked(1u << 16);
    for (std::size_t i = 0; i < asked.size(); ++i)
        asked[i] = i % 2 ? keys[std::size_t(rng() * double(keys.size()))] : (std::uint64_t(rng() * 1e5) << 32) | 100001u;
    BENCHMARK("ListTable: 65536 finds") {
        std::uint64_t s = 0;
        for (std::uint64_t k : asked) s += table.find(k);
        return s;
    };
    BENCHMARK("std::unordered_map: 65536 finds") {
        std::uint64_t s = 0;
        for (std::uint64_t k : asked) {
            const auto it = map.find(k);
            s += it == map.end() ? ListTable::kNone : it->second;
        }
        return s;
    };
    BENCHMARK("ListTable: insert 65536 keys") {
        ListTable t;
        for (std::uint32_t i = 0; i < keys.size(); ++i) t.insert(keys[i], i);
        return t.find(keys[0]);
    };
    BENCHMARK("std::unordered_map: insert 65536 keys") {
        std::unordered_map<std::uint64_t, std::uint32_t> m;
        for (std::uint32_t i = 0; i < keys.size(); ++i) m.emplace(keys[i], i);
        return m.size();
    };
}

TEST_CASE("a list tested four spheres at a time against one at a time", "[packed]") {
    // A direction list's worth of cube:8's spheres (every third one) against eye rays: the
    // loop blocker caches ran before, the packed scalar loop, and the AVX2 one where the
    // processor has it (else the same scalar loop)
    const Scene scene = makeBuiltin("cube:8");
    const PackedSpheres packed(scene);
    std::vector<int> ids;
    for (int id = 0; id < scene.size(); id += 3) ids.push_back(id);
    const std::vector<Ray> rays = randomRays(64, 8);
    auto run = [&](auto test) { return testRays(rays, test); };
    std::printf("packed spheres: AVX2 %s\n", PackedSpheres::simd() ? "on" : "off (scalar)");
    BENCHMARK("testObjectQuickly, one at a time: 64 rays x 171 ids") {
        return run([&](const Query& q, Answer& best, Counters& n) {
            for (int id : ids) testObjectQuickly(scene, q, id, best, n);
        });
    };
    BENCHMARK("PackedSpheres scalar: 64 rays x 171 ids") {
        return run([&](const Query& q, Answer& best, Counters& n) {
            packed.testNearestFirstScalar(scene, q, ids.data(), nullptr, ids.size(), best, n);
        });
    };
    BENCHMARK("PackedSpheres, picked at run time: 64 rays x 171 ids") {
        return run([&](const Query& q, Answer& best, Counters& n) {
            packed.testNearestFirst(scene, q, ids.data(), nullptr, ids.size(), best, n);
        });
    };
}

TEST_CASE("the complete search's scan, four spheres at a time against one at a time", "[scan]") {
    // Every object of cube:5 and cube:8 against eye rays: SphereBatch::test() one sphere at
    // a time, and testAll() (four at a time where the processor has AVX2, else the same loop)
    for (const char* spec : {"cube:5", "cube:8"}) {
        const Scene scene = makeBuiltin(spec);
        SphereBatch batch;
        for (int id = 0; id < scene.size(); ++id) batch.add(scene, id);
        const std::vector<Ray> rays = randomRays(64, 5);
        auto run = [&](bool four) {
            return testRays(rays, [&](const Query& q, Answer& best, Counters& n) {
                if (four)
                    batch.testAll(scene, q, best, n);
                else
                    batch.test(scene, q, 0, batch.size(), best, n);
            });
        };
        BENCHMARK(std::string(spec) + ": one at a time, 64 rays") { return run(false); };
        BENCHMARK(std::string(spec) + ": four at a time (picked at run time), 64 rays") { return run(true); };
    }
}

TEST_CASE("a cell's quick test, eight at a time against one at a time", "[directions]") {
    // DirectionLists::quickTest on 512 random aims (a cube:8 site's order), AVX2 against scalar
    Random rng(5);
    const std::size_t count = 512;
    std::vector<float> x(count), y(count), z(count), cosB(count), sinB(count);
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 v = glm::normalize(Vec3(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)));
        const double beta = rng.uniform(0.0, 0.3);
        x[k] = float(v.x), y[k] = float(v.y), z[k] = float(v.z);
        cosB[k] = float(std::cos(beta)), sinB[k] = float(std::sin(beta));
    }
    const DirectionLists::QuickCone c{0.0f, 0.0f, 1.0f, 0.8f, 0.6f};
    std::vector<std::uint64_t> maybe(count / 64), sure(count / 64);
    auto run = [&](bool simd) {
        DirectionLists::quickTest(c, x.data(), y.data(), z.data(), cosB.data(), sinB.data(), count, maybe.data(),
                                  sure.data(), simd);
        return maybe[0] ^ sure[1];
    };
    BENCHMARK("quickTest scalar: 512 aims") { return run(false); };
    BENCHMARK("quickTest, picked at run time: 512 aims") { return run(true); };
}

TEST_CASE("direction lists picked from their site's order against culled and sorted", "[directions]") {
    // Every cell of 40 of cube:8's objects, built anew each time: the lists are the same
    const Scene scene = makeBuiltin("cube:8");
    const LinearSearch linear(scene);
    const BlockerLists sites(scene, linear, true);
    auto build = [&](bool siteOrders) {
        DirectionLists lists(scene, linear, sites, siteOrders);
        Counters n;
        for (int site = 0; site < 40; ++site)
            for (int cell = 0; cell < 24; ++cell) {
                const int face = cell / 4, i = cell / 2 % 2, j = cell % 2;
                Vec3 d{0.0};
                d[face / 2] = face % 2 ? -1.0 : 1.0;
                d[(face / 2 + 1) % 3] = i ? 0.5 : -0.5;
                d[(face / 2 + 2) % 3] = j ? 0.5 : -0.5;
                std::uint32_t memo = std::uint32_t(-1);
                lists.get(site, glm::normalize(d), memo, n);
            }
        return n.directionListEntries;
    };
    BENCHMARK("culled through the hierarchy and sorted: 960 lists") { return build(false); };
    BENCHMARK("picked from each site's order: 960 lists") { return build(true); };
}
