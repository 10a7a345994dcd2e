// Tutorial 02's check: rc::segmentDistance, rc::safetyRadius and rc::SafetyCylinder::contains
// (your tutorials/02-safety-cylinder/exercise.cpp in a student build) against independent
// oracles, whose answers are data (oracles.h, oracle_data.txt): the distance against a
// search along the segment in long double, the containment test against that distance
// sampled at points along the new segment, and the radius against the gap to the nearest
// other sphere by that distance, on random cases and on cube:4's eye rays. Then what the renderer makes of them: the cylinder cache's
// picture of cube:4 equals the uncached one, and its hits fall in a stated range.
//
// Each run shows your functions every recorded case in a frame of its own
// (tutorial_frame.h): its points and spheres rotated, moved and scaled by a power of two,
// drawn from a seed (std::random_device, or $TUTORIAL_02_SEED to repeat a run; failures
// print it). An expected distance is the recorded one times the scale.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include "geometry/intersection.h"
#include "geometry/safety_cylinder.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/linear_search.h"
#include "oracles.h"
#include "tutorial_frame.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {
double closeEnough(double scale) { return 1e-9 * std::max(1.0, scale); }

using tutorial::segmentGap;

// The run's seed, said with every failure so that the run can be repeated
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_02_SEED");
    return seed;
}
std::string seedNote() {
    return " [this run's frames: TUTORIAL_02_SEED=" + std::to_string(runSeed()) + " repeats them]";
}

// A frame for a case of size about `size`: shifts up to 10 sizes, so that the rotation and
// shift round the coordinates your code sees by some 1e-14 sizes, 10^5 times inside the
// check's tolerance (1e-9 of the size). Your functions' answers in the frame, brought back
// to the case's units (the scale is a power of two: dividing by it rounds nothing)
tutorial::Frame frame(tutorial::Random& frames, double size) { return tutorial::randomFrame(frames, 10.0 * size, 4); }
double yourDistance(const tutorial::Frame& f, const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b) {
    return rc::segmentDistance(f.point(p), f.point(a), f.point(b)) / f.scale;
}
double yourRadius(const tutorial::Frame& f, const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a,
                  const rc::Vec3& b) {
    std::vector<rc::Sphere> moved;
    for (const rc::Sphere& s : spheres) moved.push_back(f.sphere(s));
    return rc::safetyRadius(moved, hit, f.point(a), f.point(b)) / f.scale;
}
bool yourContains(const tutorial::Frame& f, const rc::Vec3& a, const rc::Vec3& b, double radius, const rc::Vec3& p,
                  const rc::Vec3& q) {
    return rc::SafetyCylinder{f.point(a), f.point(b), f.scale * radius}.contains(f.point(p), f.point(q));
}

// Where `ray` meets sphere `s` (kNoHit if it does not), by the library's textbook roots, not by
// rc::sphereRootsStable: that is tutorial 06's exercise, and this check must not wait for it
// (the oracle's answers are found by these points' exact bits)
double hitDistance(const rc::Ray& ray, const rc::Sphere& s) {
    const rc::SphereRoots r = rc::sphereRootsTextbook(ray, s);
    return !r.hit ? rc::kNoHit : r.t0 > 0.0 ? r.t0 : r.t1 > 0.0 ? r.t1 : rc::kNoHit;
}

// A capsule: every point within `radius` of the segment a-b
struct Capsule {
    rc::Vec3 a, b;
    double radius;
    // The oracle: is every one of 17 points spread along p-q within the radius?
    bool contains(const rc::Vec3& p, const rc::Vec3& q) const { return tutorial::capsuleContains(a, b, radius, p, q); }
};
}  // namespace

TEST_CASE("segmentDistance agrees with the oracle on random points and segments", "[tutorial02]") {
    INFO("each case is shown to your code rotated, moved and scaled" << seedNote());
    tutorial::Random rnd(1985), frames(rc::mixKey(runSeed(), 1));
    for (int i = 0; i < 3000; ++i) {
        const double scale = rnd.logUniform(-3.0, 4.0);
        const rc::Vec3 a = scale * rnd.inBox(1.0);
        // Sometimes a degenerate segment, sometimes a very short one
        const rc::Vec3 b = i % 10 == 0 ? a : a + scale * rnd.logUniform(-4.0, 0.5) * rnd.direction();
        const rc::Vec3 p = scale * rnd.inBox(2.0);
        const double want = segmentGap(p, a, b);
        const double got = yourDistance(frame(frames, scale), p, a, b);
        INFO(std::setprecision(17) << "case " << i << ": point (" << p.x << ", " << p.y << ", " << p.z
                                   << "), segment (" << a.x << ", " << a.y << ", " << a.z << ") to (" << b.x
                                   << ", " << b.y << ", " << b.z << "), scale " << scale << ": expected " << want
                                   << ", yours " << got);
        REQUIRE(std::abs(got - want) <= closeEnough(scale));
    }
}

TEST_CASE("contains holds what the sampled capsule holds", "[tutorial02]") {
    INFO("each case is shown to your code rotated, moved and scaled" << seedNote());
    tutorial::Random rnd(85), frames(rc::mixKey(runSeed(), 2));
    int inside = 0, tested = 0, oneEndOnly = 0;
    for (int i = 0; i < 3000; ++i) {
        Capsule cyl{rnd.inBox(5.0), rnd.inBox(5.0), rnd.uniform(0.1, 3.0)};
        if (i % 10 == 0) cyl.b = cyl.a;  // a capsule around a point is a sphere
        // Points around the segment, about half of them inside the capsule
        auto near = [&] {
            return cyl.a + rnd.uniform(-0.3, 1.3) * (cyl.b - cyl.a) +
                   rnd.uniform(0.0, 1.3) * cyl.radius * rnd.direction();
        };
        const rc::Vec3 p = near(), q = near();
        // Skip points within rounding of the capsule's surface
        const double dp = segmentGap(p, cyl.a, cyl.b) - cyl.radius;
        const double dq = segmentGap(q, cyl.a, cyl.b) - cyl.radius;
        if (std::abs(dp) < 1e-6 || std::abs(dq) < 1e-6) continue;
        const bool want = cyl.contains(p, q);
        INFO(std::setprecision(17) << "case " << i << ": capsule radius " << cyl.radius << " around a segment of length "
                     << glm::length(cyl.b - cyl.a) << "; p is " << (dp <= 0 ? "inside" : "outside")
                     << ", q is " << (dq <= 0 ? "inside" : "outside") << "; expected "
                     << (want ? "inside" : "not inside"));
        REQUIRE(yourContains(frame(frames, 5.0), cyl.a, cyl.b, cyl.radius, p, q) == want);
        inside += want;
        oneEndOnly += (dp <= 0) != (dq <= 0);
        ++tested;
    }
    // The cases test both answers, and segments with one end in and one out
    CHECK(inside > tested / 10);
    CHECK(inside < tested - tested / 10);
    CHECK(oneEndOnly > tested / 10);
}

namespace {
// The gap from the segment a-b to the nearest sphere but `hit`, by the oracle
double gap(const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a, const rc::Vec3& b) {
    return tutorial::sphereGap(spheres, hit, a, b);
}
}  // namespace

TEST_CASE("safetyRadius is the gap to the nearest other sphere", "[tutorial02]") {
    INFO("each case is shown to your code rotated, moved and scaled" << seedNote());
    tutorial::Random rnd(1985), frames(rc::mixKey(runSeed(), 3));
    for (int i = 0; i < 1000; ++i) {
        std::vector<rc::Sphere> spheres(1 + rnd.index(12));
        for (rc::Sphere& s : spheres) s = {rnd.inBox(6.0), rnd.uniform(0.1, 1.5)};
        const int hit = rnd.index(int(spheres.size()));
        const rc::Vec3 a = rnd.inBox(6.0), b = i % 7 == 0 ? a : rnd.inBox(6.0);
        const double want = gap(spheres, hit, a, b), got = yourRadius(frame(frames, 6.0), spheres, hit, a, b);
        INFO(std::setprecision(17) << "case " << i << ": " << spheres.size() << " spheres, the ray hit sphere " << hit << "; expected radius "
                     << want << ", yours " << got
                     << (spheres.size() == 1 ? " (no other sphere: nothing limits the capsule)" : ""));
        if (std::isinf(want))
            REQUIRE(got == want);
        else
            REQUIRE(std::abs(got - want) <= closeEnough(6.0));
    }
}

TEST_CASE("the safety radius and a cache hit on cube:4's eye rays", "[tutorial02]") {
    const rc::Scene s = rc::makeBuiltin("cube:4");
    std::vector<rc::Sphere> spheres;
    for (const rc::Object& o : s.objects) spheres.push_back(o.bound);
    const rc::LinearSearch search(s);
    const int n = 32;
    const rc::RayGenerator camera(s.camera, n, n);
    // The picture: every pixel whose eye ray hits a sphere, bright where the cylinder of
    // the pixel before it (your radius, your containment test) answers it, dark where
    // the cache misses; magenta where your answer differs from the oracle's capsule
    std::string picture;
    {
        tutorial::Picture pic(n, n);
        int wrong = 0;
        for (int p = 1; p < n * n; ++p) {
            rc::Query q, next;
            q.ray = camera.primary((p - 1) % n, (p - 1) / n);
            next.ray = camera.primary(p % n, p / n);
            rc::Counters count;
            const rc::Answer hit = search.nearest(q, count), now = search.nearest(next, count);
            if (now.object < 0) continue;
            tutorial::Rgb c = tutorial::shade(tutorial::labelColour(now.object), 0.3);
            const double t = hit.object == now.object ? hitDistance(q.ray, spheres[hit.object]) : rc::kNoHit;
            const double t2 = hit.object == now.object ? hitDistance(next.ray, spheres[now.object]) : rc::kNoHit;
            if (t < rc::kNoHit && t2 < rc::kNoHit) {  // the same sphere (and not grazed: the textbook roots meet it)
                const rc::Vec3 h = q.ray.at(t), h2 = next.ray.at(t2);
                const double want = gap(spheres, hit.object, q.ray.o, h);
                const rc::SafetyCylinder yours{q.ray.o, h, rc::safetyRadius(spheres, hit.object, q.ray.o, h)};
                const bool mine = yours.contains(next.ray.o, h2);
                if (mine) c = tutorial::labelColour(now.object);
                if (mine != Capsule{q.ray.o, h, want}.contains(next.ray.o, h2)) c = {255, 0, 255}, ++wrong;
            }
            pic.set(p % n, p / n, c);
        }
        picture = pic.save("cube4", 10);
        tutorial::announcePicture("cube:4, bright: answered by the previous pixel's cylinder; magenta: " +
                                      std::to_string(wrong) + " pixel(s) answered differently from the oracle",
                                  picture);
    }
    INFO(std::setprecision(17) << "your cylinders on cube:4 (magenta: answered differently from the oracle): " << picture);
    INFO("cube:4 is shown to your code rotated, moved and scaled; the numbers below are the scene's" << seedNote());
    tutorial::Random frames(rc::mixKey(runSeed(), 4));
    const tutorial::Frame moved = frame(frames, 20.0);
    int hits = 0, tested = 0;
    for (int p = 0; p + 1 < n * n; ++p) {
        rc::Query q;
        q.ray = camera.primary(p % n, p / n);
        rc::Counters count;
        const rc::Answer hit = search.nearest(q, count);
        if (hit.object < 0) continue;
        const double th = hitDistance(q.ray, spheres[hit.object]);
        if (!(th < rc::kNoHit)) continue;  // grazing: the textbook roots miss
        const rc::Vec3 h = q.ray.at(th);
        const double want = gap(spheres, hit.object, q.ray.o, h);
        const double mine = yourRadius(moved, spheres, hit.object, q.ray.o, h);
        INFO(std::setprecision(17) << "pixel (" << p % n << ", " << p / n << "): expected radius " << want << ", yours " << mine);
        REQUIRE(std::abs(mine - want) <= closeEnough(20.0));
        // The next pixel's ray, to the same sphere: would the cylinder answer it?
        rc::Query next;
        next.ray = camera.primary((p + 1) % n, (p + 1) / n);
        const double t = hitDistance(next.ray, spheres[hit.object]);
        if (!(t < rc::kNoHit)) continue;
        const rc::Vec3 h2 = next.ray.at(t);
        const Capsule cyl{q.ray.o, h, want};
        const double d2 = segmentGap(h2, q.ray.o, h) - want;
        if (std::abs(d2) < 1e-9) continue;
        INFO(std::setprecision(17) << "the next pixel's segment to the same sphere");
        REQUIRE(yourContains(moved, q.ray.o, h, mine, next.ray.o, h2) == cyl.contains(next.ray.o, h2));
        hits += cyl.contains(next.ray.o, h2);
        ++tested;
    }
    CHECK(hits > 0);
    CHECK(hits < tested);
}

TEST_CASE("the cylinder cache draws cube:4 as the complete search does", "[tutorial02]") {
    // What the renderer makes of your measures: the cylinder cache answers rays with your
    // distance (rc::SafetyCylinder::distance); its picture must equal the uncached one
    // pixel for pixel, and it must answer a share of the rays (the reference solution: the
    // counts printed below)
    const auto scene = std::make_shared<const rc::Scene>(rc::makeBuiltin("cube:4"));
    auto render = [&](rc::CacheKind cache) {
        rc::RenderOptions o;
        o.width = o.height = 48;
        o.cache = cache;
        o.verify = cache != rc::CacheKind::None;
        rc::RenderSession session(scene, o);
        session.run();
        return std::make_pair(session.takeImage(), session.counters());
    };
    const auto [plain, uncached] = render(rc::CacheKind::None);
    const auto [cached, n] = render(rc::CacheKind::Cylinder);
    int differ = 0, first = -1;
    for (int p = 0; p < 48 * 48; ++p)
        if (plain.value(p) != cached.value(p)) differ += 1, first = first < 0 ? p : first;
    std::printf("tutorial 02: cube:4 at 48x48 with the cylinder cache: %llu hits, %llu misses, %llu cylinders built, "
                "%d pixel(s) differ from the uncached picture\n",
                (unsigned long long)n.hits, (unsigned long long)n.misses, (unsigned long long)n.cylindersBuilt, differ);
    INFO(std::setprecision(17) << differ << " pixel(s) differ from the uncached picture (first: pixel " << first
                               << "); the complete search disagrees with " << n.verifyDisagreements
                               << " cached answer(s); hits " << n.hits << ", misses " << n.misses);
    REQUIRE(n.verifyDisagreements == 0);
    REQUIRE(differ == 0);
    // The stated range: the reference solution's 1,861 hits on these rays, within a tenth
    // (a cylinder that never answers draws the right picture too)
    REQUIRE(n.hits >= 1675u);
    REQUIRE(n.hits <= 2047u);
    (void)uncached;
}
