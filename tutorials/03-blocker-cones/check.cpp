// Tutorial 03's check: tutorial::hullDistance against rc::hullDistance, and the blocker
// lists built with it against the library's rc::BlockerLists.
#include <algorithm>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "exercise.h"
#include "geometry/cone.h"
#include "scene/builtin_scenes.h"
#include "search/blocker_lists.h"
#include "search/complete_search.h"
#include "tutorial_random.h"

namespace {

// A random pair of spheres: ordinary, one a point (the eye, a light), equal radii (a
// cylinder), or one inside the other
void randomPair(tutorial::Random& rnd, int kind, rc::Sphere& a, rc::Sphere& b) {
    a = {rnd.inBox(3.0), rnd.uniform(0.1, 2.0)};
    b = {rnd.inBox(3.0), rnd.uniform(0.1, 2.0)};
    switch (kind % 5) {
        case 1: a.r = 0.0; break;
        case 2: b.r = 0.0; break;
        case 3: b.r = a.r; break;
        case 4: b = {a.c + rnd.uniform(0.0, 0.4) * a.r * rnd.direction(), rnd.uniform(0.05, 0.5) * a.r}; break;
        default: break;
    }
}

}  // namespace

TEST_CASE("hullDistance agrees with the library's outside the hull", "[tutorial03]") {
    tutorial::Random rnd(1986);
    int outside = 0, inside = 0;
    for (int i = 0; i < 50000; ++i) {
        rc::Sphere a, b;
        randomPair(rnd, i, a, b);
        // Anywhere, or near the axis of the pair, where the cone is
        const rc::Vec3 p = i % 2 ? rnd.inBox(6.0)
                                 : a.c + rnd.uniform(-0.2, 1.2) * (b.c - a.c) +
                                       rnd.uniform(0.0, 1.5) * std::max(a.r, b.r) * rnd.direction();
        const double want = rc::hullDistance(p, a, b);
        const double got = tutorial::hullDistance(p, a, b);
        INFO("case " << i << ": a = (" << a.c.x << ", " << a.c.y << ", " << a.c.z << ") r " << a.r << ", b = ("
                     << b.c.x << ", " << b.c.y << ", " << b.c.z << ") r " << b.r << "; expected " << want
                     << ", got " << got);
        if (want > 1e-9) {
            // Outside: the distance is exact, whatever way it is computed
            REQUIRE(std::abs(got - want) <= 1e-9 * std::max(1.0, want));
            ++outside;
        } else if (want < -1e-9) {
            // Inside: only the sign is asked for
            REQUIRE(got <= 1e-9);
            ++inside;
        }
    }
    CHECK(outside > 1000);
    CHECK(inside > 1000);
}

TEST_CASE("meetsHull decisions built on hullDistance agree with the library's", "[tutorial03]") {
    tutorial::Random rnd(1984);
    for (int i = 0; i < 50000; ++i) {
        rc::Sphere a, b;
        randomPair(rnd, i, a, b);
        const rc::Vec3 c = i % 2 ? rnd.inBox(6.0)
                                 : a.c + rnd.uniform(-0.2, 1.2) * (b.c - a.c) +
                                       rnd.uniform(0.0, 3.0) * std::max(a.r, b.r) * rnd.direction();
        const rc::Sphere s{c, rnd.uniform(0.0, 1.5)};
        const double margin = rc::hullDistance(s.c, a, b) - s.r;
        if (std::abs(margin) < 1e-7) continue;  // within rounding of touching
        INFO("case " << i);
        REQUIRE((tutorial::hullDistance(s.c, a, b) <= s.r) == rc::meetsHull(s, a, b, 0.0));
    }
}

TEST_CASE("blocker lists of cube:4 built with hullDistance equal the library's", "[tutorial03]") {
    const rc::Scene s = rc::makeBuiltin("cube:4");
    const rc::LinearSearch linear(s);
    rc::BlockerLists lists(s, linear);
    rc::Counters n;
    // Every pair of origin (the eye, a light or a sphere) and target (a sphere or a light)
    std::vector<int> sites;
    for (int id = 0; id < s.size(); ++id) sites.push_back(id);
    sites.push_back(lists.eyeSite());
    for (int k = 0; k < int(s.lights.size()); ++k) sites.push_back(lists.lightSite(k));
    int nonEmpty = 0;
    for (int origin : sites)
        for (int target : sites) {
            if (origin == target) continue;
            const rc::Sphere a = lists.siteSphere(origin), b = lists.siteSphere(target);
            std::vector<int> mine;
            for (int id = 0; id < s.size(); ++id)
                if (id != target && tutorial::hullDistance(s.objects[id].bound.c, a, b) <= s.objects[id].bound.r)
                    mine.push_back(id);
            // The library keeps its lists nearest first; compare them as sets
            std::vector<int> want = lists.get(origin, target, n).ids;
            std::sort(want.begin(), want.end());
            INFO("origin site " << origin << ", target site " << target);
            REQUIRE(mine == want);
            nonEmpty += !want.empty();
        }
    CHECK(nonEmpty > 100);
}
