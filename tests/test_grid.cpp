// The uniform grid returns exactly what the linear scan returns, and caches sit in front of it.
#include <catch2/catch.hpp>

#include <memory>

#include <glm/geometric.hpp>

#include "cull_queries.h"
#include "random_scenes.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/linear_search.h"
#include "search/uniform_grid.h"
#include "uniform.h"

using namespace rc;
using rc::testing::HullQuery;
using rc::testing::Layout;

TEST_CASE("grid and linear scan agree on random rays, ties included", "[grid][exact]") {
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 21, 60);
        const LinearSearch linear(scene);
        const UniformGrid grid(scene);
        Random rng(5);
        const Uniform u{-1.0, 1.0};
        Counters a, b;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 o = Vec3(u(rng), u(rng), u(rng)) * 6.0;
            const Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            const double tmax = (i % 3 == 0) ? 4.0 * std::abs(u(rng)) : kNoHit;
            const Query q{{o, d}, tmax, {}, RayKind::Primary, -1};
            INFO(scene.name << " ray " << i);
            REQUIRE(grid.nearest(q, b) == linear.nearest(q, a));
        }
        // the grid tests far fewer objects
        REQUIRE(b.intersectionTests < a.intersectionTests);
    }
}

TEST_CASE("every cache in front of the grid gives the linear image", "[grid][exact][image]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:6"));
    RenderOptions o;
    o.width = o.height = 48;
    RenderSession reference(scene, o);
    reference.run();
    for (CacheKind c : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker}) {
        for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
            RenderOptions g = o;
            g.accel = AccelKind::Grid;
            g.cache = c;
            g.order = order;
            g.verify = true;
            RenderSession s(scene, g);
            s.run();
            INFO(toString(c) << " " << toString(order));
            REQUIRE(s.counters().verifyDisagreements == 0);
            REQUIRE(s.image().rgb8() == reference.image().rgb8());
        }
    }
}

namespace {
/// `n` spheres of radius `r` at the points `at(i)`, one material, one light.
template <class At>
Scene manySpheres(int n, double r, At at) {
    Scene s;
    s.name = "many";
    s.materials.push_back({Vec3(0.9, 0.4, 0.3), 0.7, 0.3, 20.0, 0.0, 1.0});
    s.lights.push_back({Vec3(5, 6, 8), Vec3(1.0)});
    for (int i = 0; i < n; ++i) s.addSphere({at(i), r}, 0);
    s.camera.from = Vec3(0.0, 0.0, 10.0);
    s.camera.at = Vec3(0.0);
    s.camera.up = Vec3(0, 1, 0);
    s.camera.angle = 45.0;
    s.camera.width = s.camera.height = 16;
    s.finalize();
    return s;
}

/// `count` random rays from a box of half-side `spread`; each agrees with the scan.
void agreesWithScan(const Scene& scene, const UniformGrid& grid, int count, double spread) {
    const LinearSearch linear(scene);
    Random rng(11);
    const Uniform u{-1.0, 1.0};
    Counters a, b;
    for (int i = 0; i < count; ++i) {
        const Vec3 o = Vec3(u(rng), u(rng), u(rng)) * spread;
        const Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + (i % 2 ? Vec3(0, 0, 1e-12) : Vec3(0.0)));
        const Query q{{o, d}, kNoHit, {}, RayKind::Primary, -1};
        INFO("ray " << i);
        REQUIRE(grid.nearest(q, b) == linear.nearest(q, a));
    }
    // along an axis too: the walk's zero-direction branches
    for (int k = 0; k < 3; ++k) {
        Vec3 d(0.0);
        d[k] = -1.0;
        Vec3 o(0.0);
        o[k] = 3.0 * spread;
        const Query q{{o, d}, kNoHit, {}, RayKind::Primary, -1};
        REQUIRE(grid.nearest(q, b) == linear.nearest(q, a));
    }
}
}  // namespace

TEST_CASE("coincident spheres give a coarse grid of bounded size, not wrapped offsets", "[grid][memory]") {
    // 34,000 unit spheres at one point: a fine grid would list each in every one of its
    // 2 million cells (7e10 references; offsets in 32 bits wrapped and crashed)
    const Scene scene = manySpheres(34000, 1.0, [](int) { return Vec3(0.0); });
    const UniformGrid grid(scene);
    const std::array<int, 3> res = grid.resolution();
    const std::int64_t cells = std::int64_t(res[0]) * res[1] * res[2];
    REQUIRE(cells <= UniformGrid::kMaxCells);
    REQUIRE(grid.references() <= std::max(UniformGrid::kMinReferenceCap, UniformGrid::kReferencesPerObject * 34000));
    // every cell lists every sphere (they all overlap all of it)
    REQUIRE(grid.references() == cells * 34000);
    REQUIRE(grid.objectsInBox(Vec3(-0.1), Vec3(0.1)).size() == 34000);
    agreesWithScan(scene, grid, 50, 3.0);
}

TEST_CASE("a flat scene and tiny spheres in a huge box stay exact", "[grid][memory]") {
    // all in the plane z = 0
    const Scene flat = manySpheres(3000, 0.01, [](int i) { return Vec3(i % 60, i / 60, 0.0) * 0.1; });
    const UniformGrid flatGrid(flat);
    REQUIRE(flatGrid.resolution()[2] == 1);
    REQUIRE(flatGrid.references() < 3000 * 8);
    agreesWithScan(flat, flatGrid, 400, 4.0);
    // 2,000 tiny spheres in the unit cube, two huge ones far out at the corners of the box
    Random rng(4);
    const Uniform u{0.0, 1.0};
    const Scene tiny = manySpheres(2002, 0.001, [&](int i) {
        if (i == 0) return Vec3(-1e6);
        if (i == 1) return Vec3(1e6);
        return Vec3(u(rng), u(rng), u(rng));
    });
    const UniformGrid tinyGrid(tiny);
    agreesWithScan(tiny, tinyGrid, 400, 1.0);
}

TEST_CASE("grid culls find exactly what a scan over every object finds", "[grid][cull]") {
    const Scene scene = testing::randomScene(Layout::Overlapping, 9, 150);
    const LinearSearch linear(scene, LinearSearch::Regions::Scan);
    const UniformGrid grid(scene);
    Random rng(8);
    const Uniform u{-6.0, 6.0};
    int nonEmpty = 0;
    std::vector<int> near;
    for (int i = 0; i < 400; ++i) {
        // small spheres (a ring of cells around the segment) and large ones (a box)
        const double scale = i % 4 == 0 ? 1.0 : 12.0;
        const Sphere from{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / scale};
        const Sphere to{{u(rng), u(rng), u(rng)}, std::abs(u(rng)) / scale};
        HullQuery all(from, to), some(from, to);
        linear.cull(all);
        grid.cull(some);
        std::sort(some.ids.begin(), some.ids.end());
        REQUIRE(some.ids == all.ids);
        nonEmpty += !all.ids.empty();
        // objectsNearSegment holds every object whose bounding sphere comes within the radius
        grid.objectsNearSegment(from.c, to.c, all.radius, near);
        std::sort(near.begin(), near.end());
        for (int id = 0; id < scene.size(); ++id) {
            const Sphere& b = scene.objects[id].bound;
            if (segmentDistance(b.c, from.c, to.c) - b.r <= all.radius)
                REQUIRE(std::binary_search(near.begin(), near.end(), id));
        }
    }
    REQUIRE(nonEmpty > 100);
}

TEST_CASE("grid rays that start on a surface agree with the scan", "[grid][exact]") {
    for (Layout layout : {Layout::Overlapping, Layout::Nested, Layout::Transparent, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 33, 80);
        const LinearSearch linear(scene);
        const UniformGrid grid(scene);
        Random rng(2);
        const Uniform u{-1.0, 1.0};
        Counters a, b;
        int onSurface = 0;
        for (int i = 0; i < 4000; ++i) {
            // a first hit from outside, then a ray leaving (or entering) the surface it hit
            const Vec3 o = Vec3(u(rng), u(rng), u(rng)) * 8.0;
            const Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)) * 2.5 - o);  // towards the objects
            const Answer first = linear.nearest({{o, d}, kNoHit, {}, RayKind::Primary, -1}, a);
            if (first.object < 0) continue;
            ++onSurface;
            const Vec3 p = o + first.t * d;
            const Vec3 d2 = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            for (bool inside : {false, true}) {
                const Query q{{p, d2}, i % 2 ? kNoHit : 2.0, {first.object, inside}, RayKind::Reflection, -1};
                INFO(scene.name << " ray " << i << (inside ? " inside" : " outside"));
                REQUIRE(grid.nearest(q, b) == linear.nearest(q, a));
            }
        }
        REQUIRE(onSurface > 500);
    }
}
