// Tutorial 02's check: tutorial::segmentDistance against rc::segmentDistance, and the
// capsule test and safety radius built on it against rc::SafetyCylinder.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "exercise.h"
#include "geometry/safety_cylinder.h"
#include "scene/builtin_scenes.h"
#include "search/complete_search.h"
#include "tutorial_random.h"

namespace {
double closeEnough(double scale) { return 1e-9 * std::max(1.0, scale); }
}  // namespace

TEST_CASE("segmentDistance agrees with the library's on random points and segments", "[tutorial02]") {
    tutorial::Random rnd(1985);
    for (int i = 0; i < 20000; ++i) {
        const double scale = rnd.logUniform(-3.0, 4.0);
        const rc::Vec3 a = scale * rnd.inBox(1.0);
        // Sometimes a degenerate segment, sometimes a very short one
        const rc::Vec3 b = i % 10 == 0 ? a : a + scale * rnd.logUniform(-4.0, 0.5) * rnd.direction();
        const rc::Vec3 p = scale * rnd.inBox(2.0);
        const double want = rc::segmentDistance(p, a, b);
        INFO("case " << i << ": scale " << scale << ", expected " << want);
        REQUIRE(std::abs(tutorial::segmentDistance(p, a, b) - want) <= closeEnough(scale));
    }
}

TEST_CASE("a capsule built on segmentDistance holds what rc::SafetyCylinder holds", "[tutorial02]") {
    tutorial::Random rnd(85);
    int inside = 0, tested = 0;
    for (int i = 0; i < 20000; ++i) {
        rc::SafetyCylinder cyl{rnd.inBox(5.0), rnd.inBox(5.0), rnd.uniform(0.1, 3.0)};
        // Points around the segment, about half of them inside the capsule
        auto near = [&] {
            return cyl.a + rnd.uniform(-0.3, 1.3) * (cyl.b - cyl.a) +
                   rnd.uniform(0.0, 1.3) * cyl.radius * rnd.direction();
        };
        const rc::Vec3 p = near(), q = near();
        // Skip points within rounding of the capsule's surface
        const double dp = rc::segmentDistance(p, cyl.a, cyl.b) - cyl.radius;
        const double dq = rc::segmentDistance(q, cyl.a, cyl.b) - cyl.radius;
        if (std::abs(dp) < 1e-6 || std::abs(dq) < 1e-6) continue;
        const bool mine = tutorial::segmentDistance(p, cyl.a, cyl.b) <= cyl.radius &&
                          tutorial::segmentDistance(q, cyl.a, cyl.b) <= cyl.radius;
        INFO("case " << i);
        REQUIRE(mine == cyl.contains(p, q));
        inside += mine;
        ++tested;
    }
    CHECK(inside > tested / 10);
    CHECK(inside < tested - tested / 10);
}

TEST_CASE("the safety radius of cube:4's eye rays", "[tutorial02]") {
    // R = min over the other spheres j of (distance from c_j to the segment) - r_j
    const rc::Scene s = rc::makeBuiltin("cube:4");
    const rc::LinearSearch search(s);
    const rc::RayGenerator camera(s.camera, 32, 32);
    for (int p = 0; p < 32 * 32; ++p) {
        rc::Query q;
        q.ray = camera.primary(p % 32, p / 32);
        rc::Counters n;
        const rc::Answer hit = search.nearest(q, n);
        if (hit.object < 0) continue;
        const rc::Vec3 h = q.ray.at(hit.t);
        double mine = rc::kNoHit, want = rc::kNoHit;
        for (int j = 0; j < s.size(); ++j) {
            if (j == hit.object) continue;
            const rc::Sphere& b = s.objects[j].bound;
            mine = std::min(mine, tutorial::segmentDistance(b.c, q.ray.o, h) - b.r);
            want = std::min(want, rc::segmentDistance(b.c, q.ray.o, h) - b.r);
        }
        INFO("pixel " << p);
        REQUIRE(std::abs(mine - want) <= closeEnough(20.0));
    }
}
