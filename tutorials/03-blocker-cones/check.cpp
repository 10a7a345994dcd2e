// Tutorial 03's check: rc::Hull (your tutorials/03-blocker-cones/exercise.cpp in a student
// build) against an independent oracle, computed in long double by another method than the
// reference's. The blocker lists of cube:4 are checked against lists the oracle builds
// sphere by sphere. The oracle's answers are data (oracles.h, oracle_data.txt); the oracle
// stays with the instructor.
//
// Each run shows your hull every case in a frame of its own (tutorial_frame.h): the spheres
// and the point rotated, moved and scaled by a power of two, drawn from a seed
// (std::random_device, or $TUTORIAL_03_SEED to repeat a run; failures print it); cube:4 is
// shown moved the same way, its spheres numbered in a shuffled order. The expected
// distance is the recorded one times the scale.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "scene/builtin_scenes.h"
#include "search/blocker_lists.h"
#include "search/linear_search.h"
#include "oracles.h"
#include "tutorial_frame.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {

using tutorial::hullGap;

// Your hull's distance
double yours(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b) { return rc::Hull(a, b).distance(p); }

// The run's seed, said with every failure so that the run can be repeated
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_03_SEED");
    return seed;
}
std::string seedNote() {
    return " [this run's frames: TUTORIAL_03_SEED=" + std::to_string(runSeed()) + " repeats them]";
}

// Your hull's distance in the frame `f`, brought back to the case's units (the scale is a
// power of two: dividing by it rounds nothing). The frame's rotation and shift round the
// coordinates your hull sees by a few ulps of 20 (its shifts reach 10, the cases' points
// 6): some 1e-14 in distance, 10^5 times inside kRelativeTolerance
double yours(const tutorial::Frame& f, const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b) {
    return yours(f.point(p), f.sphere(a), f.sphere(b)) / f.scale;
}

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

// The picture: a slice through the axis of one pair of spheres (the plane z = 0). Blue
// is your hull, pale yellow where yours is larger than the true one (allowed), magenta
// where a point of the true hull is outside yours. Circles are spheres of the scene:
// orange on your list, grey not, yellow on yours only (extra), magenta left off.
std::string drawHull() {
    const rc::Sphere a{{-3.0, 0.0, 0.0}, 1.5}, b{{3.0, 0.6, 0.0}, 0.6};
    const int w = 180, h = 120;
    const double scale = 12.0 / w;  // world units per pixel; x in [-6, 6], y in [-4, 4]
    auto world = [&](double px, double py) { return rc::Vec3{-6.0 + px * scale, 4.0 - py * scale, 0.0}; };
    auto pixel = [&](const rc::Vec3& p, double& px, double& py) { px = (p.x + 6.0) / scale, py = (4.0 - p.y) / scale; };
    tutorial::Picture pic(w, h, {250, 250, 250});
    int leftOut = 0;
    const std::string slice = tutorial::hullSlice(a, b, w, h, -6.0, 4.0, scale);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const rc::Vec3 p = world(x + 0.5, y + 0.5);
            const bool mine = yours(p, a, b) <= 0.0, want = slice[std::size_t(y) * w + x] == '1';
            if (mine) pic.set(x, y, want ? tutorial::Rgb{120, 160, 230} : tutorial::Rgb{250, 235, 150});
            else if (want) pic.set(x, y, {255, 0, 255}), ++leftOut;
        }
    double px, py;
    for (const rc::Sphere& s : {a, b}) {
        pixel(s.c, px, py);
        pic.circle(px, py, s.r / scale, {20, 140, 40});
    }
    tutorial::Random rnd(2);
    for (int i = 0; i < 40; ++i) {
        const rc::Sphere s{{rnd.uniform(-5.5, 5.5), rnd.uniform(-3.5, 3.5), 0.0}, rnd.uniform(0.15, 0.45)};
        if (glm::length(s.c - a.c) - a.r < s.r || glm::length(s.c - b.c) - b.r < s.r) continue;  // overlaps a or b
        const bool mine = yours(s.c, a, b) <= s.r, want = hullGap(s.c, a, b) <= s.r;
        pixel(s.c, px, py);
        const tutorial::Rgb c = mine && want ? tutorial::Rgb{240, 140, 20}
                                : mine       ? tutorial::Rgb{230, 210, 40}
                                : want       ? tutorial::Rgb{255, 0, 255}
                                             : tutorial::Rgb{150, 150, 150};
        if (mine || want) pic.disc(px, py, s.r / scale, c);
        pic.circle(px, py, s.r / scale, {60, 60, 60});
    }
    const std::string path = pic.save("hull", 3);
    tutorial::announcePicture("your hull of two spheres and its blockers; magenta: " + std::to_string(leftOut) +
                                  " pixel(s) of the true hull outside yours, or blockers left off",
                              path);
    return path;
}

}  // namespace

// The distance must be exact outside the hull, to rounding: the relative tolerance of a
// double computation against the long double oracle (the reference is within it on every
// case). A smaller distance is a larger solid than the hull (a capsule, a cone without its
// caps, a bounding ball): its lists stay correct but are not the paper's.
constexpr double kRelativeTolerance = 1e-9;
// A list may hold a sphere the oracle's leaves off only where rounding decides: one that
// touches the hull to within a few ulps. Lists longer than this many times the oracle's
// hold more than that (the reference's equal the oracle's; the capsule of the larger radius
// makes cube:4's 1.11 times as long).
constexpr double kMaxExtraFactor = 1.01;

TEST_CASE("hullDistance is exact outside the hull and never puts a point of the hull outside it", "[tutorial03]") {
    INFO(std::setprecision(17) << "your hull in a slice through its axis (magenta: left out): " << drawHull());
    INFO("each case is shown to your hull rotated, moved and scaled; the numbers below are the case's own" << seedNote());
    tutorial::Random rnd(1986);
    tutorial::Random frames(rc::mixKey(runSeed(), 1));
    int outside = 0, inside = 0;
    for (int i = 0; i < 5000; ++i) {
        rc::Sphere a, b;
        randomPair(rnd, i, a, b);
        // Anywhere, or near the axis of the pair, where the cone is
        const rc::Vec3 p = i % 2 ? rnd.inBox(6.0)
                                 : a.c + rnd.uniform(-0.2, 1.2) * (b.c - a.c) +
                                       rnd.uniform(0.0, 1.5) * std::max(a.r, b.r) * rnd.direction();
        const double want = double(hullGap(p, a, b));
        const tutorial::Frame frame = tutorial::randomFrame(frames, 10.0, 4);
        const double got = yours(frame, p, a, b);
        INFO(std::setprecision(17) << "case " << i << ": a = (" << a.c.x << ", " << a.c.y << ", " << a.c.z << ") r " << a.r << ", b = ("
                     << b.c.x << ", " << b.c.y << ", " << b.c.z << ") r " << b.r << "; p = (" << p.x << ", " << p.y
                     << ", " << p.z << "); expected " << want << ", got " << got);
        if (want > 1e-9) {
            // Outside: the exact distance. More would leave a sphere that meets the hull off
            // its list; less measures a larger solid than the hull
            const double tolerance = kRelativeTolerance * std::max(1.0, want);
            {
                INFO(std::setprecision(17) << "your distance is larger than the true one: a sphere this close would be left off the list");
                REQUIRE(got <= want + tolerance);
            }
            INFO(std::setprecision(17) << "your distance is less than the true one: you measure a larger solid than the "
                                          "hull (both spheres and the cone between them, nothing more)");
            REQUIRE(got >= want - tolerance);
            ++outside;
        } else if (want < -1e-9) {
            INFO(std::setprecision(17) << (std::isnan(got) ? "this point is inside the hull, and your distance is NaN "
                                                             "(a square root of a negative number? one sphere inside "
                                                             "the other leaves no cone between them)"
                                                           : "this point is inside the hull, but your distance says outside"));
            REQUIRE(got <= 1e-9);
            ++inside;
        }
    }
    WARN("hullDistance: all " << outside << " points outside the hull got the exact distance");
    CHECK(outside > 1000);
    CHECK(inside > 500);
}

TEST_CASE("meetsHull decisions built on hullDistance keep every sphere that meets the hull", "[tutorial03]") {
    INFO("each case is shown to your hull rotated, moved and scaled" << seedNote());
    tutorial::Random rnd(1984);
    tutorial::Random frames(rc::mixKey(runSeed(), 2));
    int meets = 0, extra = 0;
    for (int i = 0; i < 5000; ++i) {
        rc::Sphere a, b;
        randomPair(rnd, i, a, b);
        const rc::Vec3 c = i % 2 ? rnd.inBox(6.0)
                                 : a.c + rnd.uniform(-0.2, 1.2) * (b.c - a.c) +
                                       rnd.uniform(0.0, 3.0) * std::max(a.r, b.r) * rnd.direction();
        const rc::Sphere s{c, rnd.uniform(0.0, 1.5)};
        const double margin = double(hullGap(s.c, a, b)) - s.r;
        if (std::abs(margin) < 1e-7) continue;  // within rounding of touching
        const bool want = margin <= 0.0;
        const bool mine = yours(tutorial::randomFrame(frames, 10.0, 4), s.c, a, b) <= s.r;
        INFO(std::setprecision(17) << "case " << i << ": a sphere that meets the hull, left out");
        if (want) REQUIRE(mine);
        meets += want;
        extra += mine && !want;
    }
    INFO(std::setprecision(17) << "spheres that meet the hull: " << meets << "; extra spheres your hull takes in: " << extra);
    REQUIRE(extra <= (kMaxExtraFactor - 1.0) * meets);
}

TEST_CASE("blocker lists of cube:4 built with your hull hold the oracle's", "[tutorial03]") {
    const rc::Scene s = rc::makeBuiltin("cube:4");
    const rc::LinearSearch linear(s);
    const rc::BlockerLists lists(s, linear);  // only for its sites (the eye, the lights, the spheres)
    // Every pair of origin (the eye, a light or a sphere) and target (a sphere or a light)
    std::vector<rc::Sphere> spheres;
    for (const rc::Object& o : s.objects) spheres.push_back(o.bound);
    std::vector<int> sites;
    for (int id = 0; id < s.size(); ++id) sites.push_back(id);
    sites.push_back(lists.eyeSite());
    for (int k = 0; k < int(s.lights.size()); ++k) sites.push_back(lists.lightSite(k));
    // The scene as your hull sees it this run: moved by a random frame, sphere j numbered
    // shown[j], the pairs asked in a shuffled order; your lists are mapped back to the
    // scene's numbers
    INFO("cube:4 is shown to your hull rotated, moved, scaled and renumbered; the numbers below are the scene's"
         << seedNote());
    tutorial::Random rnd(rc::mixKey(runSeed(), 3));
    const tutorial::Frame frame = tutorial::randomFrame(rnd, 10.0, 4);
    std::vector<int> shown(spheres.size()), scene(spheres.size());
    for (int j = 0; j < s.size(); ++j) shown[j] = j;
    for (int j = s.size() - 1; j > 0; --j) std::swap(shown[j], shown[rnd.index(j + 1)]);
    std::vector<rc::Sphere> moved(spheres.size());
    for (int j = 0; j < s.size(); ++j) moved[shown[j]] = frame.sphere(spheres[j]), scene[shown[j]] = j;
    std::vector<std::pair<int, int>> pairs;
    for (int origin : sites)
        for (int target : sites)
            if (origin != target) pairs.emplace_back(origin, target);
    for (int k = int(pairs.size()) - 1; k > 0; --k) std::swap(pairs[k], pairs[rnd.index(k + 1)]);
    long nonEmpty = 0, libraryTotal = 0, extra = 0;
    for (const auto& [origin, target] : pairs) {
        const rc::Sphere a = lists.siteSphere(origin), b = lists.siteSphere(target);
        const rc::Hull hull(frame.sphere(a), frame.sphere(b));
        std::vector<int> mine;
        for (int k = 0; k < s.size(); ++k) {
            if (scene[k] == target) continue;
            if (hull.distance(moved[k].c) <= moved[k].r) mine.push_back(scene[k]);
        }
        std::sort(mine.begin(), mine.end());
        // The oracle's list: every sphere but the target that meets the hull by more than rounding
        const std::vector<int> want = tutorial::blockerList(a, b, spheres, target);
        std::vector<int> missing;
        std::set_difference(want.begin(), want.end(), mine.begin(), mine.end(), std::back_inserter(missing));
        INFO(std::setprecision(17) << "origin site " << origin << ", target site " << target << ": your list leaves out "
                            << missing.size() << " potential blocker(s), the first is sphere "
                            << (missing.empty() ? -1 : missing.front()));
        REQUIRE(missing.empty());
        extra += long(mine.size() - want.size());
        libraryTotal += long(want.size());
        nonEmpty += !want.empty();
    }
    WARN("cube:4's blocker lists: the oracle's hold " << libraryTotal << " spheres, yours " << libraryTotal + extra
                                                        << " (" << extra << " extra)");
    INFO(std::setprecision(17) << "your lists hold " << extra << " extra spheres on top of the oracle's " << libraryTotal
                            << ": more than " << kMaxExtraFactor << " times as long, the cache loses its point");
    REQUIRE(double(libraryTotal + extra) <= kMaxExtraFactor * double(libraryTotal));
    CHECK(nonEmpty > 100);
}
