// The hull of two spheres (blocker cones) and the capsule (cylinder of safety).
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/safety_cylinder.h"
#include "uniform.h"

using namespace rc;


TEST_CASE("hull distance: equal radii make a capsule", "[hull]") {
    const Sphere a{Vec3(-1, 0, 0), 0.5}, b{Vec3(1, 0, 0), 0.5};
    REQUIRE(hullDistance(Vec3(0, 2, 0), a, b) == Approx(1.5));
    REQUIRE(hullHalfAngle(a, b) == 0.0);
}

TEST_CASE("hull distance: one sphere inside the other is the larger sphere", "[hull]") {
    const Sphere big{Vec3(0, 0, 0), 2.0}, small{Vec3(0.5, 0, 0), 0.5};
    REQUIRE(hullDistance(Vec3(3, 0, 0), big, small) == Approx(1.0));
    REQUIRE(hullDistance(Vec3(3, 0, 0), small, big) == Approx(1.0));
}

TEST_CASE("hull distance: a point and a sphere make the eye or light cone", "[hull]") {
    const Sphere eye{Vec3(0, 0, 5), 0.0}, s{Vec3(0, 0, 0), 1.0};
    // half-angle asin(r/d)
    REQUIRE(hullHalfAngle(s, eye) == Approx(std::asin(1.0 / 5.0)));
    // the point inside the sphere: the hull is the sphere
    const Sphere inside{Vec3(0.2, 0, 0), 0.0};
    REQUIRE(hullDistance(Vec3(0, 3, 0), inside, s) == Approx(2.0));
}

TEST_CASE("meetsHull: a sphere meets the hull when its radius reaches it, slack only adds", "[hull]") {
    // Distances worked out by hand, not by hullDistance
    auto reaches = [](const Vec3& c, double gap, const Sphere& a, const Sphere& b) {
        CHECK(meetsHull({c, gap + 1e-9}, a, b, 0.0));
        CHECK_FALSE(meetsHull({c, gap - 1e-6}, a, b, 0.0));
        CHECK(meetsHull({c, gap - 1e-12}, a, b, 1e-9));  // within the slack
        CHECK_FALSE(meetsHull({c, gap - 1e-6}, a, b, 1e-9));
    };
    // A capsule of radius 1 from (0,0,0) to (4,0,0): 3 - 1 above its middle, 7 - 4 - 1 past its end
    const Sphere a{Vec3(0, 0, 0), 1.0}, b{Vec3(4, 0, 0), 1.0};
    reaches(Vec3(2, 3, 0), 2.0, a, b);
    reaches(Vec3(7, 0, 0), 2.0, a, b);
    // The cone from the point (10,0,0) to the sphere of radius 2 at the origin: its side
    // leaves the axis at asin(2/10), so (5,3,0) lies 3 cos - 5 sin = 3 sqrt(0.96) - 1 from it
    // (its foot, 5 cos + 3 sin = 5.5 from the apex, falls before the tangent point at sqrt(96))
    const Sphere big{Vec3(0, 0, 0), 2.0}, apex{Vec3(10, 0, 0), 0.0};
    reaches(Vec3(5, 3, 0), 3.0 * std::sqrt(0.96) - 1.0, big, apex);
    reaches(Vec3(5, 3, 0), 3.0 * std::sqrt(0.96) - 1.0, apex, big);
    // Behind the big sphere the nearest point is on it: 5 - 2
    reaches(Vec3(-5, 0, 0), 3.0, big, apex);
    // A sphere inside the hull meets it, whatever its size
    CHECK(meetsHull({Vec3(5, 0.1, 0), 1e-6}, big, apex, 0.0));
}

TEST_CASE("capsule containment is the containment of both endpoints", "[cylinder]") {
    const SafetyCylinder cyl{Vec3(0, 0, 0), Vec3(10, 0, 0), 1.0};
    REQUIRE(cyl.contains(Vec3(0, 0.5, 0), Vec3(10, -0.5, 0.5)));
    REQUIRE(cyl.contains(Vec3(-0.9, 0, 0), Vec3(10.9, 0, 0)));
    REQUIRE_FALSE(cyl.contains(Vec3(0, 0.5, 0), Vec3(11.5, 0, 0)));
    REQUIRE_FALSE(cyl.contains(Vec3(5, 1.01, 0), Vec3(6, 0, 0)));
    // convexity: every point between two contained endpoints is contained
    Random rng(9);
    const Uniform u{-1.5, 11.5};
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p(u(rng), u(rng) / 10, u(rng) / 10), q(u(rng), u(rng) / 10, u(rng) / 10);
        if (!cyl.contains(p, q)) continue;
        const SafetyCylinder wider{cyl.a, cyl.b, cyl.radius + 1e-12};
        for (double l = 0; l <= 1.0; l += 0.05) {
            const Vec3 x = p + l * (q - p);
            REQUIRE(wider.contains(x, x));
        }
    }
    REQUIRE(segmentDistance(Vec3(5, 3, 4), Vec3(0), Vec3(10, 0, 0)) == Approx(5.0));
}

TEST_CASE("a segment's start is exactly 0 from it: the cylinder probe does not measure it", "[cylinder]") {
    // CylinderOfSafety::probe takes 0 for a ray from the kept segment's start (an eye ray
    // after an eye ray) instead of measuring it: the measure must give exactly 0 there
    Random rng(42);
    const Uniform u{-1e3, 1e3};
    for (int i = 0; i < 2000; ++i) {
        const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        REQUIRE(segmentDistance(a, a, b) == 0.0);
        REQUIRE(segmentDistance(a, a, a) == 0.0);  // a segment that is a point
        REQUIRE(SafetyCylinder{a, b * 1e-9, 1.0}.distance(a) == 0.0);
    }
    // and the end is not the start: it is measured
    REQUIRE(segmentDistance(Vec3(0, 1, 0), Vec3(0), Vec3(1, 0, 0)) == 1.0);
}
