// The instructor's tests of the hull of two spheres against computations of it apart from
// the library: dense sampling, and a ternary search over the spheres between the two. Each
// of them computes tutorial 03's answer, so the student edition leaves this folder out
// (scripts/student_edition.py); tests/test_hull.cpp and tests/test_caches.cpp keep the rest.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "../random_scenes.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/blocker_cache.h"
#include "../uniform.h"

using namespace rc;
using testing::Layout;

namespace {
// The hull of two spheres is the union of the spheres interpolated between them
double bruteHullDistance(const Vec3& p, const Sphere& a, const Sphere& b) {
    double best = 1e300;
    for (int i = 0; i <= 20000; ++i) {
        const double l = i / 20000.0;
        const Vec3 c = a.c + l * (b.c - a.c);
        const double r = a.r + l * (b.r - a.r);
        best = std::min(best, glm::length(p - c) - r);
    }
    return best;
}

void checkAgainstBruteForce(const Sphere& a, const Sphere& b, std::uint64_t seed) {
    Random rng(seed);
    const Uniform u{-4.0, 4.0};
    for (int i = 0; i < 300; ++i) {
        const Vec3 p(u(rng), u(rng), u(rng));
        const double exact = hullDistance(p, a, b);
        const double brute = bruteHullDistance(p, a, b);
        INFO("p = " << p.x << "," << p.y << "," << p.z << " exact " << exact << " brute " << brute);
        if (brute >= 0.0) {
            // outside the hull the distance is exact; sampling overestimates by a hair
            REQUIRE(exact == Approx(brute).margin(1e-6));
        } else {
            REQUIRE(exact <= 1e-9);  // inside: negative
        }
    }
}

/// How far sphere `s` lies from the hull of spheres `a` and `b`, computed apart from the
/// library: the hull is the union of the spheres interpolated between a and b, and the gap
/// to the sphere interpolated at l is convex in l, so a ternary search finds its least value
double hullGap(const Sphere& s, const Sphere& a, const Sphere& b) {
    auto gap = [&](double l) { return glm::length(s.c - (a.c + l * (b.c - a.c))) - (a.r + l * (b.r - a.r)) - s.r; };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
        const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
        if (gap(m1) < gap(m2)) hi = m2;
        else lo = m1;
    }
    return std::min({gap(0.0), gap(1.0), gap(0.5 * (lo + hi))});
}
}  // namespace

TEST_CASE("hull distance agrees with dense sampling", "[hull]") {
    checkAgainstBruteForce({Vec3(-1, 0, 0), 1.0}, {Vec3(2, 0.5, 0), 0.3}, 1);
    checkAgainstBruteForce({Vec3(0, -1, 1), 0.2}, {Vec3(0, 2, -1), 1.2}, 2);
    // equal radii make a capsule
    checkAgainstBruteForce({Vec3(-1, 0, 0), 0.5}, {Vec3(1, 0, 0), 0.5}, 3);
    // one sphere inside the other is the larger sphere
    checkAgainstBruteForce({Vec3(0, 0, 0), 2.0}, {Vec3(0.5, 0, 0), 0.5}, 4);
    // overlapping spheres
    checkAgainstBruteForce({Vec3(0, 0, 0), 1.0}, {Vec3(1.2, 0, 0), 0.7}, 5);
    // a point and a sphere make the eye or light cone
    checkAgainstBruteForce({Vec3(0, 0, 5), 0.0}, {Vec3(0, 0, 0), 1.0}, 6);
}

TEST_CASE("blocker lists hold the objects a second computation of the hull finds", "[cache][blocker]") {
    auto scene = std::make_shared<const Scene>(testing::randomScene(Layout::Overlapping, 9));
    RenderOptions o;
    o.cache = CacheKind::Blocker;
    RenderSession s(scene, o);
    s.run();
    const BlockerLists* lists = s.strategy().blockerLists();
    REQUIRE(lists != nullptr);
    const int sites = lists->sites();
    // Every list built holds exactly the objects whose bounding spheres meet the hull of
    // its two sites, the target excepted, as a second computation of the hull finds them
    // (up to a hair of rounding either way)
    const double tolerance = 1e-7 * scene->extent();
    std::uint64_t found = 0, listed = 0, borderline = 0;
    for (int origin = 0; origin < sites; ++origin)
        for (int target = 0; target < sites; ++target) {
            const std::vector<int>* list = lists->find(origin, target);
            if (!list) continue;
            ++found;
            const Sphere a = lists->siteSphere(origin), b = lists->siteSphere(target);
            for (int id = 0; id < scene->size(); ++id) {
                const double gap = hullGap(scene->objects[id].bound, a, b);
                const bool in = std::count(list->begin(), list->end(), id) == 1;
                INFO("pair " << origin << " -> " << target << " object " << id << " gap " << gap);
                if (id == lists->siteObject(target)) {
                    REQUIRE_FALSE(in);
                } else if (gap < -tolerance) {
                    REQUIRE(in);
                } else if (gap > tolerance) {
                    REQUIRE_FALSE(in);
                } else {
                    ++borderline;
                }
                listed += in;
            }
        }
    REQUIRE(found > 0);
    REQUIRE(listed > found);   // the lists are not empty
    REQUIRE(borderline < 10);  // the tolerance decides almost nothing
}

TEST_CASE("trio's third sphere lies wholly inside the hull of the other two", "[builtin][hull]") {
    const Scene s = makeBuiltin("trio");
    REQUIRE(s.spheres.size() == 3);
    const Sphere &a = s.spheres[0], &b = s.spheres[1], &c = s.spheres[2];
    // The hull of two balls holds every ball between them (centres and radii blended):
    // the third lies wholly inside one of those
    bool inside = false;
    for (int k = 0; k <= 100; ++k) {
        const double f = k / 100.0;
        const Sphere m{a.c + (b.c - a.c) * f, a.r + (b.r - a.r) * f};
        inside = inside || glm::length(c.c - m.c) + c.r <= m.r;
    }
    CHECK(inside);
}
