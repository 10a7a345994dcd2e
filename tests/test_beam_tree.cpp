// The beam tree on hand-made images, and coherence.
#include <catch2/catch.hpp>

#include <memory>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"

using namespace rc;

TEST_CASE("beam tree of hand-made images", "[beam]") {
    SECTION("two halves are two beams") {
        BeamTreeBuilder b(4, 4);
        for (int p = 0; p < 16; ++p) b.record(0, p, -1, false, (p % 4) < 2 ? 1 : 2);
        REQUIRE(b.build().nodes == 2);
        REQUIRE(b.build().averageRayTreeSize == 1.0);
        REQUIRE(b.build().coherence == 0.5);
    }
    SECTION("a checkerboard is one beam per pixel") {
        BeamTreeBuilder b(4, 4);
        for (int p = 0; p < 16; ++p) b.record(0, p, -1, false, ((p % 4) + (p / 4)) % 2);
        REQUIRE(b.build().nodes == 16);
    }
    SECTION("disconnected pixels hitting the same object are separate beams") {
        BeamTreeBuilder b(5, 1);
        const int hits[5] = {3, 3, 7, 3, 3};
        for (int p = 0; p < 5; ++p) b.record(0, p, -1, false, hits[p]);
        REQUIRE(b.build().nodes == 3);
        const std::vector<int> l = b.labels(0);
        REQUIRE(l[0] == l[1]);
        REQUIRE(l[1] != l[3]);
    }
    SECTION("same hit from a different origin is another beam; paths count separately") {
        BeamTreeBuilder b(2, 2);
        for (int p = 0; p < 4; ++p) b.record(0, p, -1, false, 1);        // eye rays: one beam
        b.record(1, 0, 1, false, 2);                                     // reflections from 1
        b.record(1, 1, 1, false, 2);
        b.record(1, 2, 5, false, 2);                                     // from another origin
        b.record(1, 3, 1, true, 2);                                      // from inside 1
        const BeamTreeStats s = b.build();
        REQUIRE(s.nodes == 1 + 3);
        REQUIRE(s.averageRayTreeSize == 2.0);
        REQUIRE(s.coherence == Approx(0.5));
    }
}

TEST_CASE("coherence is 1 when one sphere fills the screen", "[beam]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("fill"));
    RenderSession s(scene, {});
    BeamTreeBuilder b(s.width(), s.height());
    s.addSink(&b);
    s.run();
    const BeamTreeStats stats = b.build();
    REQUIRE(stats.coherence == Approx(1.0));
    REQUIRE(stats.nodes == std::int64_t(stats.averageRayTreeSize));
}

TEST_CASE("the beam tree does not depend on the cache or order", "[beam]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:3"));
    std::int64_t nodes = -1;
    for (CacheKind c : {CacheKind::None, CacheKind::Blocker}) {
        for (OrderKind o : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
            RenderOptions opt;
            opt.width = opt.height = 32;
            opt.cache = c;
            opt.order = o;
            RenderSession s(scene, opt);
            BeamTreeBuilder b(32, 32);
            s.addSink(&b);
            s.run();
            const std::int64_t n = b.build().nodes;
            if (nodes < 0) nodes = n;
            REQUIRE(n == nodes);
        }
    }
}
