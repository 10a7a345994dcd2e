// Breadth-first order: every ray once, the same image as scanline, a small queue.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "order/breadth_first_order.h"
#include "order/deferral_policy.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"

using namespace rc;

namespace {
struct PrimaryCounter final : TraceSink {
    explicit PrimaryCounter(int pixels) : primaries(pixels, 0), rays(pixels, 0) {}
    void onEvent(const TraceEvent& e) override {
        if (e.deferred) {
            ++deferred;
            return;
        }
        if (e.task.query.kind == RayKind::Primary) ++primaries[e.task.pixel];
        ++rays[e.task.pixel];
        order.push_back(e.task.pixel);
    }
    std::vector<int> primaries, rays, order;
    int deferred = 0;
};
}  // namespace

TEST_CASE("bfs traces every pixel's eye ray exactly once and every ray of scanline order", "[bfs]") {
    for (const char* name : {"cube:4", "glass", "pair"}) {
        auto scene = std::make_shared<const Scene>(makeBuiltin(name));
        for (CacheKind cache : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker}) {
            RenderOptions o;
            o.width = 48;
            o.height = 40;
            o.cache = cache;
            RenderSession scan(scene, o);
            PrimaryCounter scanCount(48 * 40);
            scan.addSink(&scanCount);
            scan.run();
            o.order = OrderKind::BreadthFirst;
            o.band = 8;
            RenderSession bfs(scene, o);
            PrimaryCounter bfsCount(48 * 40);
            bfs.addSink(&bfsCount);
            bfs.run();
            INFO(name << " " << toString(cache));
            for (int p = 0; p < 48 * 40; ++p) {
                REQUIRE(bfsCount.primaries[p] == 1);
                REQUIRE(bfsCount.rays[p] == scanCount.rays[p]);
            }
            REQUIRE(bfs.image().rgb8() == scan.image().rgb8());
            // bfs visits in another order than scanline
            REQUIRE(bfsCount.order != scanCount.order);
            // without a cache nothing is deferred
            if (cache == CacheKind::None) REQUIRE(bfsCount.deferred == 0);
        }
    }
}

TEST_CASE("bfs queue stays within the band: at most width x band rays", "[bfs][queue]") {
    // Each pixel of the band is queued at most once at a time (its state says Queued), so
    // the fill queue never exceeds width * band; in practice it is a small multiple of the
    // band height, the length of a region's boundary.
    auto scene = std::make_shared<const Scene>(readNffFile(std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff"));
    for (int band : {4, 16, 64}) {
        RenderOptions o;
        o.width = 128;
        o.height = 128;
        o.cache = CacheKind::Blocker;
        o.order = OrderKind::BreadthFirst;
        o.band = band;
        RenderSession s(scene, o);
        s.run();
        INFO("band " << band << " queue peak " << s.order().queuePeak());
        REQUIRE(s.order().queuePeak() > 0);
        REQUIRE(s.order().queuePeak() <= std::size_t(128 * band));
        REQUIRE(s.order().queuePeak() <= std::size_t(4 * (128 + band)));
        REQUIRE(s.order().regions() > 0);
    }
}

TEST_CASE("bfs makes fewer complete searches than scanline with a cache", "[bfs]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:5"));
    for (CacheKind cache : {CacheKind::Cylinder, CacheKind::Blocker}) {
        RenderOptions o;
        o.width = o.height = 96;
        o.cache = cache;
        RenderSession scan(scene, o);
        scan.run();
        o.order = OrderKind::BreadthFirst;
        RenderSession bfs(scene, o);
        bfs.run();
        INFO(toString(cache) << ": scanline " << scan.counters().completeSearches << ", bfs "
                             << bfs.counters().completeSearches);
        REQUIRE(bfs.counters().completeSearches < scan.counters().completeSearches);
    }
}

TEST_CASE("bfs defers misses only where a complete search is dear", "[bfs]") {
    // Blocker+ in front of a grid or a hierarchy asks every ray fully: a deferral would
    // cost a second lookup to save a cheap search. In front of the linear scan, and for
    // the paper's blocker anywhere, rays whose cheap lookup fails wait for a later region.
    auto scene = std::make_shared<const Scene>(readNffFile(std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff"));
    RenderOptions o;
    o.width = o.height = 64;
    o.order = OrderKind::BreadthFirst;
    RenderSession reference(scene, o);
    reference.run();
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
        for (CacheKind cache : {CacheKind::Blocker, CacheKind::BlockerPlus}) {
            o.accel = accel;
            o.cache = cache;
            RenderSession bfs(scene, o);
            bfs.run();
            const bool defers = !(cache == CacheKind::BlockerPlus && accel != AccelKind::Linear);
            INFO(toString(accel) << " " << toString(cache) << ": " << bfs.counters().deferrals << " deferrals");
            REQUIRE(defersMisses(cache, accel != AccelKind::Linear) == defers);
            REQUIRE((bfs.counters().deferrals > 0) == defers);
            REQUIRE(bfs.image().rgb8() == reference.image().rgb8());
        }
    }
}

TEST_CASE("progressive order traces all eye rays of a band before any deeper ray", "[progressive]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:3"));
    RenderOptions o;
    o.width = o.height = 24;
    o.order = OrderKind::Progressive;
    o.band = 0;  // the whole image
    RenderSession s(scene, o);
    int lastDepth = 1;
    struct DepthCheck final : TraceSink {
        int* last;
        bool monotone = true;
        void onEvent(const TraceEvent& e) override {
            if (e.task.depth < *last) monotone = false;
            *last = e.task.depth;
        }
    } check;
    check.last = &lastDepth;
    s.addSink(&check);
    s.run();
    REQUIRE(check.monotone);
    REQUIRE(lastDepth > 1);
}
