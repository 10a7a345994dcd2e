// Tutorial 01's check: rc::standardAlgorithm (your tutorials/01-first-ray/exercise.cpp in a
// student build, where LinearSearch runs it) against an independent oracle: every sphere's
// roots found by bisection in long double, the nearest in front taken (its answers are data:
// oracles.h, oracle_data.txt), on
// seeded random scenes and rays and on cube:3's eye rays. Then what the renderer makes of
// them: cube:3 rendered at 64x40 (eye, shadow and reflected rays the cases above never ask)
// with your loop as its complete search, and again with a BVH whose tests are your
// standardTest in a student build, is the reference picture tutorial_01_render.png pixel for
// pixel, and the loop's counted tests fall in a stated range.
#include <iomanip>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/complete_search.h"
#include "search/standard_algorithm.h"
#include "oracles.h"
#include "tutorial_frame.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {

rc::Scene randomScene(tutorial::Random& rnd, int spheres, bool twins) {
    rc::Scene s;
    s.materials.push_back({});
    for (int i = 0; i < spheres; ++i) s.addSphere({rnd.inBox(10.0), rnd.uniform(0.2, 2.5)}, 0);
    // Coincident spheres: equal distances, the lower id must win
    if (twins)
        for (int i = 0; i < spheres / 4; ++i) s.addSphere(s.spheres[rnd.index(spheres)], 0);
    s.finalize();
    return s;
}

// A random query: from a free point, or leaving (or entering) a sphere's surface
rc::Query randomQuery(tutorial::Random& rnd, const rc::Scene& s) {
    rc::Query q;
    if (rnd.chance(0.5)) {
        q.ray = {rnd.inBox(14.0), rnd.direction()};
    } else {
        const int k = rnd.index(s.size());
        const rc::Sphere& sp = s.spheres[s.objects[k].index];
        const rc::Vec3 n = rnd.direction();
        q.ray = {sp.c + sp.r * n, rnd.direction()};
        q.origin = {k, glm::dot(q.ray.d, n) < 0.0};
    }
    if (rnd.chance(0.3)) q.tmax = rnd.uniform(0.5, 20.0);  // like a shadow ray to its light
    return q;
}

}  // namespace

namespace {

// The oracle's nearest hit, with RayCache's rules: hits at tmax or beyond do not count, a
// ray leaving the surface it starts on cannot meet it again, a ray entering it meets it at
// its far root; equal distances go to the lower id. Spheres only. `ambiguous`, if given,
// is set when a root lies within rounding of 0 or of tmax (a ray starting on the surface of
// another sphere, a twin of its own): in or out is then a matter of the last bit. `tests`,
// if given, is set to the tests the complete search counts for q.
rc::Answer oracle(const rc::Scene& s, const rc::Query& q, bool* ambiguous = nullptr, long* tests = nullptr) {
    std::vector<rc::Sphere> spheres;
    for (int id = 0; id < s.size(); ++id) {
        REQUIRE(s.objects[id].shape == rc::Shape::Sphere);
        spheres.push_back(s.spheres[s.objects[id].index]);
    }
    bool unsure = false;
    long counted = 0;
    const rc::Answer a = tutorial::oracleNearest(spheres, q, unsure, counted);
    if (ambiguous) *ambiguous = unsure;
    if (tests) *tests = counted;
    return a;
}

// Your loop, and the tests it counted
rc::Answer yours(const rc::Scene& s, const rc::Query& q, rc::Counters& n) { return rc::standardAlgorithm(s, q, n); }

// The run's seed, said with every failure so that the run can be repeated
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_01_SEED");
    return seed;
}

// Scene `s` and query `q` as your loop sees them in frame `f`: every sphere moved and scaled
// alike, the objects in the same order (a tie still goes to the lower id), tmax scaled. A
// distance becomes f.scale times the case's (a power of two: exact). The rotation rounds the
// coordinates by a few ulps of 30: some 1e-14 in t, far inside agree()'s 1e-9, and far from
// the oracle's 1e-9 margin around 0 and tmax, where a case is left out as ambiguous
rc::Answer yours(const tutorial::Frame& f, const rc::Scene& s, const rc::Query& q, rc::Counters& n) {
    rc::Scene shown;
    shown.materials = s.materials;
    for (int id = 0; id < s.size(); ++id) shown.addSphere(f.sphere(s.spheres[s.objects[id].index]), 0);
    shown.finalize();
    rc::Query seen = q;
    seen.ray = f.ray(q.ray);
    if (q.tmax < rc::kNoHit) seen.tmax = q.tmax * f.scale;
    rc::Answer a = yours(shown, seen, n);
    if (a.t < rc::kNoHit) a.t /= f.scale;
    return a;
}

// Do two answers agree, up to the oracle's rounding of t?
bool agree(const rc::Answer& got, const rc::Answer& want) {
    return got.object == want.object &&
           (want.object < 0 ? got.t == rc::kNoHit : std::abs(got.t - want.t) <= 1e-9 * std::max(1.0, want.t));
}

}  // namespace

TEST_CASE("standardAlgorithm agrees with the oracle on random scenes", "[tutorial01]") {
    tutorial::Random rnd(1986);
    // Each case is shown to your loop in a frame of this run's own (TUTORIAL_01_SEED repeats it)
    tutorial::Random frames(rc::mixKey(runSeed(), 1));
    int hits = 0, cases = 0, skipped = 0;
    for (int scene = 0; scene < 40; ++scene) {
        const rc::Scene s = randomScene(rnd, 5 + rnd.index(60), scene % 4 == 0);
        for (int i = 0; i < 60; ++i) {
            const rc::Query q = randomQuery(rnd, s);
            rc::Counters n;
            bool ambiguous = false;
            long wantTests = 0;
            const rc::Answer want = oracle(s, q, &ambiguous, &wantTests);
            const rc::Answer got = yours(tutorial::randomFrame(frames, 10.0, 4), s, q, n);
            if (ambiguous) {
                ++skipped;
                continue;
            }
            INFO(std::setprecision(17) << "scene " << scene << " ray " << i << ": origin (" << q.ray.o.x << ", " << q.ray.o.y << ", "
                          << q.ray.o.z << ") direction (" << q.ray.d.x << ", " << q.ray.d.y << ", " << q.ray.d.z
                          << ") from object " << q.origin.object << (q.origin.inside ? " (inside it)" : " (outside it)")
                          << ", tmax " << q.tmax << ": the oracle finds object " << want.object << " at t = "
                          << want.t << ", yours object " << got.object << " at t = " << got.t << " after "
                          << n.intersectionTests << " counted test(s), the oracle counts " << wantTests
                          << " [this run's frames: TUTORIAL_01_SEED=" << runSeed() << " repeats them]");
            REQUIRE(got.object == want.object);
            REQUIRE(agree(got, want));
            // One counted test per object, the surface the ray leaves excepted
            REQUIRE(n.intersectionTests == std::uint64_t(wantTests));
            hits += want.object >= 0;
            ++cases;
        }
    }
    // The cases are worth something only if many rays hit, and few are left out (rays
    // leaving a sphere that has a twin start on the twin's surface: about 5% of the cases)
    CHECK(hits > cases / 4);
    CHECK(skipped < cases / 10);
}

TEST_CASE("standardTest gives a tie to the lower id, in whatever order objects are tested", "[tutorial01]") {
    // Caches and the BVH call standardTest in their own order, not by id: two coincident
    // spheres, objects 0 and 2, must come out the same whichever is tested first
    rc::Scene s;
    s.materials.push_back({});
    s.addSphere({rc::Vec3(0.0, 0.0, 5.0), 1.0}, 0);
    s.addSphere({rc::Vec3(4.0, 0.0, 5.0), 1.0}, 0);
    s.addSphere({rc::Vec3(0.0, 0.0, 5.0), 1.0}, 0);  // object 0 again
    s.finalize();
    rc::Query q;
    q.ray = {rc::Vec3(0.0), rc::Vec3(0.0, 0.0, 1.0)};
    for (const std::vector<int>& order : {std::vector<int>{2, 0, 1}, {0, 2, 1}, {1, 2, 0}}) {
        rc::Answer best;
        rc::Counters n;
        for (int id : order) rc::standardTest(s, q, id, best, n);
        INFO("objects tested in the order " << order[0] << ", " << order[1] << ", " << order[2]
                                            << ": yours keeps object " << best.object << " at t = " << best.t
                                            << "; objects 0 and 2 are the same sphere, hit at t = 4, and a tie "
                                               "goes to the lower id, 0");
        REQUIRE(best.object == 0);
        REQUIRE(std::abs(best.t - 4.0) <= 1e-12);
        REQUIRE(n.intersectionTests == 3);
    }
}

TEST_CASE("standardAlgorithm finds what the eye sees in cube:3", "[tutorial01]") {
    const rc::Scene s = rc::makeBuiltin("cube:3");
    const int w = 48, h = 48;
    const rc::RayGenerator camera(s.camera, w, h);
    // The picture: what your search sees through every pixel, each sphere in its colour,
    // shaded by the angle the ray meets it at; magenta where the complete search disagrees
    tutorial::Picture pic(w, h);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            rc::Query q;
            q.ray = camera.primary(x, y);
            rc::Counters n;
            const rc::Answer got = yours(s, q, n), want = oracle(s, q);
            tutorial::Rgb c = tutorial::labelColour(got.object);
            if (got.object >= 0 && got.t < rc::kNoHit) {
                const rc::Sphere& b = s.objects[got.object].bound;
                c = tutorial::shade(c, 0.3 + 0.7 * std::abs(glm::dot(glm::normalize(q.ray.at(got.t) - b.c), q.ray.d)));
            }
            if (!agree(got, want)) c = {255, 0, 255}, ++wrong;
            pic.set(x, y, c);
        }
    const std::string path = pic.save("cube3", 6);
    tutorial::announcePicture("what your search sees in cube:3; magenta: " + std::to_string(wrong) + " wrong pixel(s)", path);
    INFO(std::setprecision(17) << "your picture of cube:3, wrong pixels in magenta: " << path);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            rc::Query q;
            q.ray = camera.primary(x, y);
            rc::Counters n;
            const rc::Answer want = oracle(s, q);
            const rc::Answer got = yours(s, q, n);
            INFO(std::setprecision(17) << "pixel (" << x << ", " << y << "): the oracle finds object "
                                       << want.object << " at t = " << want.t << ", yours object " << got.object
                                       << " at t = " << got.t);
            REQUIRE(agree(got, want));
        }
    // What the renderer's pictures make of your loop: the reference picture, pixel for pixel
    const int off = tutorial::differingPixels(path, TUTORIAL_DIR "/tutorial_01_expected.png");
    INFO("your picture " << path << " and the reference " TUTORIAL_DIR "/tutorial_01_expected.png differ in " << off
                         << " pixel(s) (-1: not comparable)");
    REQUIRE(off == 0);
}

namespace {
// The render's complete search: your standardAlgorithm() for every ray (in a student build
// the linear scan is yours already; the instructor's build links it here)
class YourSearch final : public rc::CompleteSearch {
public:
    explicit YourSearch(const rc::Scene& scene) : CompleteSearch(scene) {}
    rc::Answer nearest(const rc::Query& q, rc::Counters& n) const override { return rc::standardAlgorithm(scene_, q, n); }
    std::string name() const override { return "your standardAlgorithm"; }
    bool cheap() const override { return false; }
};
}  // namespace

TEST_CASE("the renderer draws cube:3 with your search as the reference does", "[tutorial01]") {
    // A render of its own: 64x40 (not the 48x48 above), with shadows and reflections, so
    // most of its rays are ones no case above asked about
    const auto scene = std::make_shared<const rc::Scene>(rc::makeBuiltin("cube:3"));
    const int w = 64, h = 40;
    auto render = [&](rc::AccelKind accel, const std::string& name, rc::Counters& n) {
        rc::RenderOptions o;
        o.width = w;
        o.height = h;
        o.accel = accel;
        std::vector<std::uint8_t> rgb;
        try {
            const auto session = accel == rc::AccelKind::Linear
                                     ? std::make_unique<rc::RenderSession>(scene, o, std::make_unique<YourSearch>(*scene))
                                     : std::make_unique<rc::RenderSession>(scene, o);
            session->run();
            n = session->counters();
            rgb = session->takeImage().rgb8();
        } catch (const std::exception& e) {
            FAIL("the render with " << name << " stopped: " << e.what());
        }
        tutorial::Picture pic(w, h);
        for (int p = 0; p < w * h; ++p) pic.set(p % w, p / w, {rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]});
        return pic.save(name);
    };
    const std::string reference = TUTORIAL_DIR "/tutorial_01_render.png";
    // Your standardAlgorithm() is the linear scan's complete search: every ray of the render
    rc::Counters linear;
    const std::string path = render(rc::AccelKind::Linear, "render", linear);
    tutorial::announcePicture("cube:3 rendered with your search", path);
    const int off = tutorial::differingPixels(path, reference);
    std::printf("tutorial 01: cube:3 at %dx%d with your search: %llu rays, %llu complete searches, %llu tests, "
                "%d pixel(s) differ from the reference\n",
                w, h, (unsigned long long)linear.totalRays(), (unsigned long long)linear.completeSearches,
                (unsigned long long)linear.intersectionTests, off);
    {
        INFO("your render " << path << " and the reference " << reference << " differ in " << off
                            << " pixel(s) (-1: not comparable)");
        REQUIRE(off == 0);
    }
    {
        // The stated range: the reference solution's 8,024 complete searches and 211,184
        // tests on these rays (27 spheres a search, less the surface a ray leaves), within
        // half a percent
        INFO("your search made " << linear.intersectionTests << " counted tests in " << linear.completeSearches
                                 << " complete searches; the reference solution 211184 in 8024");
        REQUIRE(linear.completeSearches >= 7984u);
        REQUIRE(linear.completeSearches <= 8064u);
        REQUIRE(linear.intersectionTests >= 210128u);
        REQUIRE(linear.intersectionTests <= 212240u);
    }
    // The same scene through a BVH, which tests each object it reaches with your
    // standardTest() in a student build (the instructor's build keeps its own): the same picture
    rc::Counters bvh;
    const std::string viaBvh = render(rc::AccelKind::Bvh, "render-bvh", bvh);
    const int offBvh = tutorial::differingPixels(viaBvh, reference);
    INFO("cube:3 through a BVH that tests objects with your standardTest(): " << viaBvh << " and the reference "
                                                                               << reference << " differ in " << offBvh
                                                                               << " pixel(s) (-1: not comparable)");
    REQUIRE(offBvh == 0);
    REQUIRE(bvh.intersectionTests > 0u);
}
