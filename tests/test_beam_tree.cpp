// The beam tree on hand-made images, and coherence.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

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

TEST_CASE("a pixel recorded twice at one path keeps its last key", "[beam]") {
    BeamTreeBuilder b(3, 1);
    b.record(0, 0, -1, false, 1);
    b.record(0, 1, -1, false, 2);  // replaced below: then all three pixels hit 1
    b.record(0, 2, -1, false, 1);
    b.record(0, 1, -1, false, 1);
    REQUIRE(b.build().nodes == 1);
    REQUIRE(b.labels(0) == std::vector<int>{0, 0, 0});
}

TEST_CASE("a path's rays span several blocks: rolled back and merged, none lost", "[beam]") {
    // 200x100 pixels, more rays than the small blocks hold (16, 32, ..., 4096: 8176), so a
    // huge one too: stripes of 10 columns hit objects 1 and 2 in turn, 20 beams
    const int w = 200, h = 100;
    auto stripe = [](int p) { return (p % w) / 10 % 2 + 1; };
    BeamTreeBuilder b(w, h);
    for (int p = 0; p < 6000; ++p) b.record(0, p, -1, false, stripe(p));
    const BeamTreeBuilder::Mark m = b.mark();
    for (int p = 6000; p < w * h; ++p) b.record(0, p, -1, false, stripe(p));
    b.record(3, 0, 7, false, 1);
    REQUIRE(b.storedRays() == w * h + 1);
    REQUIRE(b.build().nodes == 20 + 1);

    // Back to the mark: rows 0-29 whole, and no path 3
    b.rollback(m);
    REQUIRE(b.storedRays() == 6000);
    REQUIRE(b.paths() == std::vector<int>{0});
    REQUIRE(b.build().nodes == 20);
    const std::vector<int> labels = b.labels(0);
    REQUIRE(labels[5999] >= 0);
    REQUIRE(labels[6000] == -1);

    // Recording goes on after the rollback; another builder's rays move over under the map
    for (int p = 6000; p < 8000; ++p) b.record(0, p, -1, false, stripe(p));
    BeamTreeBuilder other(w, h);
    for (int p = 8000; p < w * h; ++p) other.record(1, p, -1, false, stripe(p));
    b.merge(std::move(other), {0, 0});
    REQUIRE(other.storedRays() == 0);
    REQUIRE(b.storedRays() == w * h);
    REQUIRE(b.build().nodes == 20);
    REQUIRE(b.labels(0)[w * h - 1] == b.labels(0)[w - 1]);
}

TEST_CASE("paths of few rays take little memory; a long one grows by doubling", "[beam]") {
    // Distributed ray tracing makes hundreds of thousands of paths, most with a few rays
    BeamTreeBuilder b(100, 100);
    for (int path = 0; path < 10000; ++path) b.record(path, path, -1, false, 1);  // one ray a path
    REQUIRE(b.storedRays() == 10000);
    REQUIRE(b.reservedRays() <= 16 * 10000);
    // A path of 5000 rays: blocks of 16, 32, ..., 4096 (8176 rays), no more than twice its rays
    BeamTreeBuilder one(100, 100);
    for (int p = 0; p < 5000; ++p) one.record(0, p, -1, false, 1);
    REQUIRE(one.reservedRays() == 8176);
    REQUIRE(one.build().nodes == 1);
}

TEST_CASE("recording goes on after a merge and a rollback, in order", "[beam]") {
    // Pixels 0-29 of path 0 recorded by two builders; a pixel recorded again keeps its last ray
    BeamTreeBuilder a(10, 10), b(10, 10);
    for (int p = 0; p < 10; ++p) a.record(0, p, -1, false, 1);
    for (int p = 10; p < 20; ++p) b.record(0, p, -1, false, 1);
    a.merge(std::move(b), {0});
    for (int p = 20; p < 30; ++p) a.record(0, p, -1, false, 1);
    REQUIRE(a.storedRays() == 30);
    REQUIRE(a.build().nodes == 1);
    const BeamTreeBuilder::Mark m = a.mark();
    a.record(0, 5, -1, false, 2);  // pixel 5 again, another object: a beam of its own
    REQUIRE(a.build().nodes == 2);
    a.rollback(m);
    REQUIRE(a.storedRays() == 30);
    REQUIRE(a.build().nodes == 1);
    a.record(0, 30, -1, false, 1);
    const std::vector<int> labels = a.labels(0);
    for (int p = 0; p <= 30; ++p) REQUIRE(labels[std::size_t(p)] == 0);
    REQUIRE(labels[31] == -1);
}
