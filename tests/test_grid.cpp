// The uniform grid returns exactly what the linear scan returns, and caches sit in front of it.
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include <glm/geometric.hpp>

#include "random_scenes.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/uniform_grid.h"

using namespace rc;
using rc::testing::Layout;

TEST_CASE("grid and linear scan agree on random rays, ties included", "[grid][exact]") {
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 21, 60);
        const LinearSearch linear(scene);
        const UniformGrid grid(scene);
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
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
