// The bounding volume hierarchy returns exactly what the linear scan returns, answers the
// caches' culling queries as a scan over every object does, and caches sit in front of it.
#include <catch2/catch.hpp>

#include <memory>

#include <glm/geometric.hpp>

#include "cull_queries.h"
#include "random_scenes.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/bounding_volume_hierarchy.h"
#include "search/clearance_scan.h"
#include "search/segment_clearance.h"
#include "search/linear_search.h"
#include "uniform.h"

using namespace rc;
using rc::testing::HullQuery;
using rc::testing::Layout;
using rc::testing::NearestToSegment;


TEST_CASE("bvh and linear scan agree on random rays, ties included", "[bvh][exact]") {
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 33, 80);
        const LinearSearch linear(scene);
        const BoundingVolumeHierarchy bvh(scene);
        REQUIRE(bvh.nodeCount() >= 2 * 80 / 8 - 1);
        Random rng(9);
        const Uniform u{-1.0, 1.0};
        Counters a, b;
        int hits = 0;
        for (int i = 0; i < 20000; ++i) {
            Vec3 o = Vec3(u(rng), u(rng), u(rng)) * 6.0;
            Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            if (i % 5 == 0) d = Vec3(0.0, 0.0, d.z > 0 ? 1.0 : -1.0);  // zero direction components
            RayOrigin from;
            if (i % 4 == 1) {  // leaving or entering an object's surface
                const int k = rng.index(scene.size());
                if (scene.objects[k].shape == Shape::Sphere) {
                    const Sphere& s = scene.spheres[scene.objects[k].index];
                    const Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
                    o = s.c + s.r * n;
                    from = {k, glm::dot(d, n) < 0.0};
                }
            }
            const double tmax = (i % 3 == 0) ? 4.0 * std::abs(u(rng)) : kNoHit;
            const Query q{{o, d}, tmax, from, RayKind::Primary, -1};
            INFO(scene.name << " ray " << i);
            const Answer want = linear.nearest(q, a);
            REQUIRE(bvh.nearest(q, b) == want);
            hits += want.object >= 0;
        }
        REQUIRE(hits > 2000);
        // the hierarchy tests far fewer objects
        REQUIRE(b.intersectionTests * 4 < a.intersectionTests);
    }
}

TEST_CASE("bvh culls exactly the objects a scan over all of them finds", "[bvh][cull]") {
    const Scene scene = testing::randomScene(Layout::Overlapping, 7, 120);
    const LinearSearch linear(scene, LinearSearch::Regions::Scan);
    const BoundingVolumeHierarchy bvh(scene);
    Random rng(3);
    const Uniform u{-6.0, 6.0};
    int nonEmpty = 0;
    for (int i = 0; i < 300; ++i) {
        const Sphere from{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / 6.0};
        const Sphere to{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / 4.0};
        HullQuery all(from, to), some(from, to);
        linear.cull(all);
        bvh.cull(some);
        std::sort(some.ids.begin(), some.ids.end());
        REQUIRE(some.ids == all.ids);
        nonEmpty += !all.ids.empty();
        NearestToSegment scan(from.c, to.c), tree(from.c, to.c);
        linear.cull(scan);
        bvh.cull(tree);
        REQUIRE(tree.nearest == scan.nearest);
        REQUIRE(tree.limit == scan.limit);
    }
    REQUIRE(nonEmpty > 100);
}

TEST_CASE("the linear search culls through its hierarchy exactly as by a scan", "[bvh][cull][cylinder]") {
    // Rays are scanned, but a cache's region queries (hulls, cylinders of safety) go
    // through the hierarchy: the same objects, the same radius, fewer objects measured
    for (Layout layout : {Layout::Overlapping, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 5, 150);
        const LinearSearch tree(scene), scan(scene, LinearSearch::Regions::Scan);
        Random rng(17);
        const Uniform u{-6.0, 6.0};
        int cut = 0;
        for (int i = 0; i < 300; ++i) {
            const Sphere from{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / 6.0};
            const Sphere to{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / 4.0};
            HullQuery byScan(from, to), byTree(from, to);
            scan.cull(byScan);
            tree.cull(byTree);
            std::sort(byTree.ids.begin(), byTree.ids.end());
            REQUIRE(byTree.ids == byScan.ids);
            const int skip = i % scene.size(), skipToo = (7 * i) % scene.size();
            const double radius = scan.clearance(from.c, to.c, skip, skipToo, kNoHit);
            REQUIRE(tree.clearance(from.c, to.c, skip, skipToo, kNoHit) == radius);
            REQUIRE(tree.clearance(from.c, to.c, skip, skipToo, 0.25) == std::min(radius, 0.25));
            // Told to stop below a distance, it is exact at or above it, else a bound
            // from above that is still below it (an object nearer than the stop)
            for (double stop : {radius - 0.5, radius, radius + 1e-9, radius + 0.5}) {
                for (const CompleteSearch* search : {static_cast<const CompleteSearch*>(&tree), static_cast<const CompleteSearch*>(&scan)}) {
                    const double stopped = search->clearance(from.c, to.c, skip, skipToo, kNoHit, stop);
                    if (radius >= stop) {
                        REQUIRE(stopped == radius);
                    } else {
                        REQUIRE(stopped >= radius);
                        REQUIRE(stopped < stop);
                    }
                }
            }
            cut += radius < 0.0;
        }
        // Segments both clear of every object and inside some
        REQUIRE(cut > 10);
        REQUIRE(cut < 300);
    }
}

TEST_CASE("every cache in front of the bvh gives the linear image", "[bvh][exact][image]") {
    const std::string balls2 = std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff";
    for (const std::string& spec : {std::string("cube:6"), std::string("glass"), balls2}) {
        auto scene = std::make_shared<const Scene>(loadScene(spec));
        RenderOptions o;
        o.width = o.height = 40;
        RenderSession reference(scene, o);
        reference.run();
        for (CacheKind c : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker}) {
            for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
                RenderOptions g = o;
                g.accel = AccelKind::Bvh;
                g.cache = c;
                g.order = order;
                g.verify = true;
                RenderSession s(scene, g);
                s.run();
                INFO(spec << " " << toString(c) << " " << toString(order));
                REQUIRE(s.counters().verifyDisagreements == 0);
                REQUIRE(s.image().rgb8() == reference.image().rgb8());
                // in front of a hierarchy, a ray costs a few tests, not one per object
                REQUIRE(s.counters().intersectionTests < reference.counters().intersectionTests);
            }
        }
    }
}

TEST_CASE("in front of a hierarchy blocker+ stays cheap, the paper's blocker tests its long lists", "[bvh][bypass]") {
    // balls2: the ground polygon's bounding sphere meets every hull it is part of
    auto scene = std::make_shared<const Scene>(loadScene(std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff"));
    auto tests = [&](AccelKind accel, CacheKind cache) {
        RenderOptions o;
        o.width = o.height = 48;
        o.accel = accel;
        o.cache = cache;
        RenderSession s(scene, o);
        s.run();
        return double(s.counters().intersectionTests) / double(s.counters().totalRays());
    };
    const double searched = tests(AccelKind::Bvh, CacheKind::None);
    const double cached = tests(AccelKind::Bvh, CacheKind::BlockerPlus);
    const double paper = tests(AccelKind::Bvh, CacheKind::Blocker);
    INFO("tests per ray: bvh " << searched << ", bvh + blocker+ " << cached << ", bvh + blocker (the paper's) " << paper);
    REQUIRE(cached < 4.0 * searched);
    // The paper's cache never steps aside: it tests the ground polygon's long lists whole
    REQUIRE(paper > 5.0 * cached);
}

TEST_CASE("the clearance scan measures what the hierarchy measures, bit for bit", "[bvh][cylinder][exact]") {
    // In front of the linear scan, cylinders of safety are measured over every sphere four
    // at a time (ClearanceScan): the radius must be the hierarchy's exactly, with any count
    // of objects (a multiple of four or not), objects left out, a cap, and on every processor
    int cut = 0, capped = 0;
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        for (int count : {1, 3, 4, 5, 37, 150}) {
            const Scene scene = testing::randomScene(layout, 11 + std::uint64_t(count), count);
            const BoundingVolumeHierarchy tree(scene);
            const ClearanceScan scan(scene);
            REQUIRE(scan.size() == scene.objects.size());
            const int objects = scene.size();
            Random rng(23);
            const Uniform u{-6.0, 6.0};
            for (int i = 0; i < 200; ++i) {
                const Vec3 a{u(rng), u(rng), u(rng)};
                // A point now and then: a segment of length 0
                const Vec3 b = i % 17 == 0 ? a : Vec3{u(rng), u(rng), u(rng)};
                const int skip = i % 3 == 0 ? -1 : i % objects, skipToo = i % 5 == 0 ? -1 : (7 * i) % objects;
                const double cap = i % 4 == 0 ? 0.25 : kNoHit;
                int treeNearest = -2, scanNearest = -2, scalarNearest = -2;
                const double radius = tree.clearance(a, b, skip, skipToo, cap, -kNoHit, &treeNearest);
                REQUIRE(scan.clearance(a, b, skip, skipToo, cap, &scanNearest) == radius);
                REQUIRE(scan.clearanceScalar(a, b, skip, skipToo, cap, &scalarNearest) == radius);
                // The same object, or one at the same distance (a tie); -1 only for the cap
                REQUIRE(scanNearest == scalarNearest);
                if (treeNearest < 0) {
                    REQUIRE(scanNearest == -1);
                    ++capped;
                } else {
                    REQUIRE(scanNearest >= 0);
                    REQUIRE(scanNearest != skip);
                    REQUIRE(scanNearest != skipToo);
                    SegmentClearance measure(a, b, -1, -1, kNoHit, -kNoHit);
                    REQUIRE(measure.distance(scene.objects[std::size_t(scanNearest)].bound) == radius);
                }
                cut += radius < 0.0;
            }
        }
    }
    // Segments inside objects, clear of them, and capped
    REQUIRE(cut > 100);
    REQUIRE(capped > 100);
}
