// Checkpoints of a stepping render: going back to one and stepping on traces the same rays,
// with the same answers, counters and image, as the render did the first time.
#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"

using namespace rc;

namespace {
/// What a trace event says, compared field by field.
struct Heard {
    std::int64_t step;
    int pixel, node, depth, sample;
    std::uint64_t key;
    int kind, light, object;
    double t, ox, oy, oz, dx, dy, dz;
    int decision, reason, tests;
    bool searched, deferred;
    bool operator==(const Heard&) const = default;
};

/// Keeps every event it hears.
struct Listener final : TraceSink {
    std::vector<Heard> heard;
    void onEvent(const TraceEvent& e) override {
        const Query& q = e.task.query;
        heard.push_back({e.step, e.task.pixel, e.task.node, e.task.depth, e.task.sample, e.task.key, int(q.kind),
                         q.light, e.lookup.answer().object, e.lookup.answer().t, q.ray.o.x, q.ray.o.y, q.ray.o.z,
                         q.ray.d.x, q.ray.d.y, q.ray.d.z, int(e.lookup.decision), int(e.lookup.reason), e.tests,
                         e.lookup.searched, e.deferred});
    }
};

std::int64_t runTo(RenderSession& s, std::int64_t step) {
    while (s.steps() < step && s.step()) {
    }
    return s.steps();
}

RenderOptions small(CacheKind cache, OrderKind order) {
    RenderOptions o;
    o.width = 24;
    o.height = 20;
    o.cache = cache;
    o.order = order;
    o.band = 8;
    return o;
}
}  // namespace

TEST_CASE("A restored checkpoint steps on exactly as the render did, for every cache and order", "[checkpoint]") {
    for (const std::string spec : {"cube:3", "pair"}) {
        auto scene = std::make_shared<const Scene>(makeBuiltin(spec));
        // In front of a BVH blocker+ builds a list on its pair's second meeting: a checkpoint
        // restores the lists built since to unbuilt. Bands of one scanline: breadth-first
        // order walks the paths of a cache that defers nothing
        for (AccelKind accel : {AccelKind::Linear, AccelKind::Bvh})
        for (int band : {8, 1})
        for (CacheKind cache : allCacheKinds()) {
            for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst, OrderKind::Progressive}) {
                INFO(spec << " " << toString(cache) << " " << toString(order) << " " << toString(accel) << " band "
                          << band);
                RenderOptions o = small(cache, order);
                o.accel = accel;
                o.band = band;
                RenderSession direct(scene, o);
                while (direct.step()) {
                }
                RenderSession s(scene, o);
                Listener first;
                s.addSink(&first);
                // Two checkpoints, the second sharing the scanlines that did not change
                const std::int64_t a = direct.steps() / 5, b = direct.steps() / 2, t = direct.steps() * 4 / 5;
                REQUIRE(runTo(s, a) == a);
                const SessionCheckpoint atA = s.checkpoint();
                REQUIRE(runTo(s, b) == b);
                const SessionCheckpoint atB = s.checkpoint(&atA);
                REQUIRE(atB.image.ownBytes() < std::size_t(24 * 20 * 3 * 8));  // not the whole image
                REQUIRE(runTo(s, t) == t);
                const std::vector<std::uint8_t> image = s.image().rgb8();
                const Counters counters = s.counters();
                const std::size_t heardToT = first.heard.size();

                for (const SessionCheckpoint* c : {&atB, &atA, &atB}) {
                    s.restore(*c);
                    REQUIRE(s.steps() == c->steps);
                    REQUIRE(s.counters() == c->counters);
                    Listener again;
                    s.addSink(&again);
                    REQUIRE(runTo(s, t) == t);
                    s.removeSink(&again);
                    REQUIRE(s.image().rgb8() == image);
                    REQUIRE(s.counters() == counters);
                    // The same events as the first time from the checkpoint on
                    std::size_t from = 0;
                    while (first.heard[from].step < c->steps) ++from;
                    REQUIRE(again.heard.size() == heardToT - from);
                    REQUIRE(std::equal(again.heard.begin(), again.heard.end(), first.heard.begin() + std::ptrdiff_t(from)));
                }
                // And on to the end, as a render never stopped does
                s.removeSink(&first);
                while (s.step()) {
                }
                REQUIRE(s.image().rgb8() == direct.image().rgb8());
                REQUIRE(s.counters() == direct.counters());
                REQUIRE(s.steps() == direct.steps());
            }
        }
    }
}

TEST_CASE("A checkpoint of distributed samples restores their paths and entries", "[checkpoint]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:3"));
    for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
        RenderOptions o = small(CacheKind::BlockerPlus, order);
        o.shading.sampling.spp = 2;
        o.shading.sampling.lightRadius = 0.3;
        o.shading.sampling.shadowSamples = 2;
        RenderSession s(scene, o);
        runTo(s, 500);
        const SessionCheckpoint c = s.checkpoint();
        runTo(s, 2000);
        const std::vector<std::uint8_t> image = s.image().rgb8();
        const Counters counters = s.counters();
        const int paths = s.cacheTree().size();
        s.restore(c);
        REQUIRE(s.cacheTree().size() == c.paths.size());
        runTo(s, 2000);
        REQUIRE(s.image().rgb8() == image);
        REQUIRE(s.counters() == counters);
        REQUIRE(s.cacheTree().size() == paths);
    }
}

TEST_CASE("A checkpoint is restored only by its session, at or past it", "[checkpoint]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("pair"));
    RenderSession s(scene, small(CacheKind::Blocker, OrderKind::BreadthFirst));
    runTo(s, 200);
    const SessionCheckpoint late = s.checkpoint();
    RenderSession other(scene, small(CacheKind::Blocker, OrderKind::BreadthFirst));
    runTo(other, 400);
    REQUIRE_THROWS_AS(other.restore(late), std::invalid_argument);
    // Behind it: the blocker lists built since are a log it cannot regrow
    runTo(s, 300);
    const SessionCheckpoint later = s.checkpoint(&late);
    s.restore(late);
    REQUIRE_THROWS_AS(s.restore(later), std::invalid_argument);
    REQUIRE(s.steps() == 200);
}
