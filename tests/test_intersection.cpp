// Ray-sphere and ray-polygon intersection: rays that start on a surface, and polygons. The
// stable roots against a long double reference are the instructor's
// (tests/instructor/test_roots_oracles.cpp: the reference computes tutorial 06's answer).
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/polygon.h"
#include "uniform.h"

using namespace rc;

TEST_CASE("rays starting on a sphere: convexity instead of an epsilon", "[intersection]") {
    Random rng(11);
    const Sphere s{Vec3(1.0, 2.0, 3.0), 2.5};
    for (int i = 0; i < 2000; ++i) {
        const Vec3 n = randomUnit(rng);
        const Vec3 p = s.c + n * s.r;
        Vec3 d = randomUnit(rng);
        if (glm::dot(d, n) > 0.0) d = -d;  // heading inward
        const double t = intersectSphere({p, d}, s, Start::Entering);
        // the far side: the chord length 2 r cos(angle)
        const double chord = -2.0 * s.r * glm::dot(d, n);
        REQUIRE(t == Approx(chord).epsilon(1e-9).margin(1e-10));
        REQUIRE(intersectSphere({p, -d}, s, Start::Leaving) == kNoHit);
    }
}

TEST_CASE("a ray from inside a sphere hits its far root", "[intersection]") {
    const Sphere s{Vec3(0.0), 1.0};
    REQUIRE(intersectSphere({Vec3(0.0), Vec3(1.0, 0.0, 0.0)}, s, Start::Elsewhere) == Approx(1.0));
    REQUIRE(intersectSphere({Vec3(0.5, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0)}, s, Start::Elsewhere) == Approx(1.5));
    REQUIRE(intersectSphere({Vec3(2.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)}, s, Start::Elsewhere) == kNoHit);
}

TEST_CASE("polygon hits: inside, outside, either winding, leaving", "[intersection][polygon]") {
    Polygon square;
    REQUIRE_FALSE(makePolygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {}, square));
    Polygon reversed;
    REQUIRE_FALSE(makePolygon({{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}}, {}, reversed));
    Random rng(3);
    const Uniform u{-2.0, 2.0};
    for (int i = 0; i < 5000; ++i) {
        const Vec3 o(u(rng), u(rng), 3.0);
        const Vec3 target(u(rng), u(rng), 0.0);
        const Ray ray{o, glm::normalize(target - o)};
        const bool inside = std::abs(target.x) < 1.0 && std::abs(target.y) < 1.0;
        const double t = intersectPolygon(ray, square, false);
        REQUIRE((t < kNoHit) == inside);
        REQUIRE(intersectPolygon(ray, reversed, false) == t);
        if (inside) REQUIRE(glm::length(ray.at(t) - target) < 1e-9);
        REQUIRE(intersectPolygon(ray, square, true) == kNoHit);
    }
    Polygon bad;
    REQUIRE(makePolygon({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {}, bad).has_value());
    REQUIRE(makePolygon({{0, 0, 0}, {1, 0, 0}}, {}, bad).has_value());
}
