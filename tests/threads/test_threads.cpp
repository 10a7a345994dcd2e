// Rendering on 1, 2, 3 and 8 threads gives the same image, the same rays and the same beam
// tree; caches differ only by each thread's cold start. This file is also built alone
// (raycache_thread_tests) so that the tsan preset runs it under ThreadSanitizer.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <vector>

#include "analysis/beam_tree.h"
#include "render/parallel_render.h"
#include "scene/builtin_scenes.h"

using namespace rc;

namespace {
struct Outcome {
    ParallelRun run;
    BeamTreeStats beams;
    std::vector<int> beamsPerPath;  ///< sorted: path ids depend on which thread met them first
};

Outcome render(const std::shared_ptr<const Scene>& scene, const RenderOptions& o, int threads) {
    Outcome out;
    BeamTreeBuilder builder(o.width, o.height);
    int calls = 0;
    double last = -1.0;
    out.run = renderParallel(scene, o, threads, &builder, [&](double done) {
        // progress comes on the calling thread, grows, and stays within [0, 1]
        REQUIRE(done >= last);
        REQUIRE(done <= 1.0);
        last = done;
        ++calls;
        return true;
    });
    REQUIRE(calls >= 1);
    REQUIRE(last == 1.0);
    out.beams = builder.build();
    for (int path : builder.paths()) {
        const std::vector<int> l = builder.labels(path);
        out.beamsPerPath.push_back(*std::max_element(l.begin(), l.end()) + 1);
    }
    std::sort(out.beamsPerPath.begin(), out.beamsPerPath.end());
    return out;
}
}  // namespace

TEST_CASE("1, 2, 3 and 8 threads give the same image, rays and beam tree", "[threads]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:5"));
    for (CacheKind cache : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker}) {
        for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
            RenderOptions o;
            // 48 rows in bands of 2: the blocks of 2, 3 and 8 threads begin at band
            // boundaries, so breadth-first fills the same bands with any thread count
            o.width = 72;
            o.height = 48;
            o.band = 2;
            o.cache = cache;
            o.order = order;
            const Outcome one = render(scene, o, 1);
            REQUIRE(one.run.threads == 1);
            REQUIRE(one.run.completed);
            REQUIRE(one.beams.nodes > 0);
            for (int threads : {2, 3, 8}) {
                INFO("cache " << toString(cache) << ", order " << int(order) << ", " << threads << " threads");
                const Outcome many = render(scene, o, threads);
                REQUIRE(many.run.threads == threads);
                REQUIRE(many.run.completed);
                REQUIRE(many.run.image.rgb8() == one.run.image.rgb8());
                for (int p = 0; p < o.width * o.height; ++p) REQUIRE(many.run.image.value(p) == one.run.image.value(p));
                REQUIRE(many.run.counters.rays == one.run.counters.rays);
                REQUIRE(many.run.paths == one.run.paths);
                REQUIRE(many.beams.nodes == one.beams.nodes);
                REQUIRE(many.beams.averageRayTreeSize == one.beams.averageRayTreeSize);
                REQUIRE(many.beamsPerPath == one.beamsPerPath);
                // [cold-start-bound]
                // Each extra thread starts its block with an empty cache: at most one more
                // (or one fewer) miss, so one complete search, per ray-tree path
                const std::int64_t bound = std::int64_t(threads - 1) * one.run.paths;
                const std::int64_t searches =
                    std::int64_t(many.run.counters.completeSearches) - std::int64_t(one.run.counters.completeSearches);
                const std::int64_t hits = std::int64_t(many.run.counters.hits) - std::int64_t(one.run.counters.hits);
                const std::int64_t misses = std::int64_t(many.run.counters.misses) - std::int64_t(one.run.counters.misses);
                // [cold-start-bound]
                REQUIRE(std::llabs(searches) <= bound);
                REQUIRE(std::llabs(hits) <= bound);
                REQUIRE(std::llabs(misses) <= bound);
                if (cache == CacheKind::None) {
                    REQUIRE(searches == 0);
                    REQUIRE(many.run.counters.intersectionTests == one.run.counters.intersectionTests);
                }
            }
        }
    }
}

TEST_CASE("every cache, order and search on 1, 2, 3 and all threads, blocks cutting bands: one image", "[threads][exact]") {
    // 13 rows in bands of 3: 2 threads split at row 6, 3 threads at rows 4 and 8, so every
    // block but the first starts inside a band. Small, so that the 2 x 180 renders run in
    // seconds, under ThreadSanitizer too. glass adds transmitters (interior lists)
    for (const char* name : {"cube:4", "glass"}) {
        auto scene = std::make_shared<const Scene>(makeBuiltin(name));
        RenderOptions base;
        base.width = 20;
        base.height = 13;
        base.band = 3;
        // The oracle: no cache, scanline order, the linear scan, one thread
        const ParallelRun plain = renderParallel(scene, base, 1);
        const std::vector<std::uint8_t> expected = plain.image.rgb8();
        int renders = 0;
        for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh})
            for (CacheKind cache : allCacheKinds())
                for (OrderKind order : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst})
                    for (int threads : {1, 2, 3, 0}) {
                        RenderOptions o = base;
                        o.accel = accel;
                        o.cache = cache;
                        o.order = order;
                        o.verify = cache != CacheKind::None;
                        const ParallelRun run = renderParallel(scene, o, threads);
                        INFO(name << ": " << toString(accel) << ", " << toString(cache) << ", " << toString(order)
                                  << ", " << threads << " threads (" << run.threads << ")");
                        REQUIRE(run.completed);
                        REQUIRE(run.threads == (threads > 0 ? threads : run.threads));
                        REQUIRE(run.threads >= 1);
                        REQUIRE(run.counters.verifyDisagreements == 0);
                        REQUIRE(run.image.rgb8() == expected);
                        for (int p = 0; p < base.width * base.height; ++p)
                            REQUIRE(run.image.value(p) == plain.image.value(p));
                        REQUIRE(run.counters.rays == plain.counters.rays);
                        REQUIRE(run.paths == plain.paths);
                        ++renders;
                    }
        REQUIRE(renders == 3 * int(allCacheKinds().size()) * 3 * 4);
        REQUIRE(allCacheKinds().size() == 5);
    }
}

TEST_CASE("a parallel render can be cancelled from its progress callback", "[threads]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:4"));
    RenderOptions o;
    o.width = 512;  // many batches of rays: the first progress call comes long before the end
    o.height = 384;
    int calls = 0;
    const ParallelRun run = renderParallel(scene, o, 3, nullptr, [&](double) { return ++calls < 1; });
    REQUIRE_FALSE(run.completed);
    REQUIRE(calls == 1);
    REQUIRE(run.counters.rays[0] < std::uint64_t(o.width * o.height));
}
