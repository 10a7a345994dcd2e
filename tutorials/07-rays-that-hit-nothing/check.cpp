// Tutorial 07's check, in three graded parts:
//   basic         emptyConeAngle against the formula, and no ray inside the cone hits
//   intermediate  the cache is exact on every eye ray of three scenes, and cheaper than
//                 the cylinder of safety on rays that hit nothing and in all, and than no
//                 cache (at most three quarters of its searches on those rays); its lookups
//                 are cheap (a few sphere tests per answer, not a search)
//   challenge     a fifth of the one-empty-cone cache's complete searches on rays that
//                 hit nothing, cheaper in all, and rays that follow an empty ray answered too
// The cache sees the spheres only through CountedSpheres, which counts every test it
// makes, in every one of its functions; every n tests are charged as one more complete
// search, and a lookup of n tests or more is not an answer. The check prints the
// measurement the student reports (complete searches per beam) beside the no-cache,
// cylinder-of-safety and one-empty-cone caches, counted the same way (their rows, like which
// sphere each eye ray hits, are recorded data: oracles.h), and draws the student's cache at
// work as a PNG.
//
// Each run shows the cache each scene in a presentation of its own, drawn from a seed
// (std::random_device, or $TUTORIAL_07_SEED to repeat a run; failures print it): the
// spheres numbered in a shuffled order, the world and the eye moved together by a random
// rotation, translation and uniform scale, and the pixels asked in scanline order of the
// image flipped and turned at random, from a random row on. Which sphere each ray hits, and so every cost, is the
// scene's own; only the numbers and coordinates a cache sees change.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

// The grade report is a Catch2 event listener
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include "exercise.h"
#include "oracles.h"
#include "scene/builtin_scenes.h"
#include "search/query.h"
#include "tutorial_frame.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {

// The check's oracle for the empty cone (data: oracles.h, oracle_data.txt)
double coneAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres) {
    return tutorial::oracleConeAngle(apex, axis, spheres);
}

// The lowest-numbered sphere the ray meets at all, -1 for none (not the nearest: a ray
// just inside the empty cone must meet none)
int anyMet(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres) {
    const auto met = std::find_if(spheres.begin(), spheres.end(), [&](const rc::Sphere& s) {
        return rc::intersectSphere(ray, s, rc::Start::Elsewhere) < rc::kNoHit;
    });
    return met == spheres.end() ? -1 : int(met - spheres.begin());
}

// ---- The scene as a cache sees it: every question counted ----------------------------

// The only way a cache learns about the spheres. Every distance() and disc() is one test,
// counted here whichever function of the cache asks.
class CountedSpheres final : public tutorial::Spheres {
public:
    CountedSpheres(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye, std::uint64_t seed)
        : spheres_(spheres), eye_(eye), frames_(seed) {}
    int size() const override { return int(spheres_.size()); }
    double distance(const rc::Vec3& d, int j) const override {
        const rc::Sphere& s = sphere(j);
        return rc::intersectSphere(rc::Ray{eye_, d}, s, rc::Start::Elsewhere);
    }
    // The disc's two angles are measured with your own emptyConeAngle() (part 1, so it comes
    // first): the angle to the centre is the empty cone of a sphere of radius 0 there, and
    // the disc's radius is a right angle less the empty cone around a direction square to
    // the centre (that ray misses the sphere unless the eye is inside it)
    Disc disc(const rc::Vec3& axis, int j) const override {
        const rc::Sphere& s = sphere(j);
        const rc::Vec3 v = s.c - eye_;
        const rc::Vec3 toCentre = glm::normalize(v);
        const rc::Vec3 square =
            glm::normalize(glm::cross(toCentre, std::abs(toCentre.x) < 0.9 ? rc::Vec3{1, 0, 0} : rc::Vec3{0, 1, 0}));
        const double centre = emptyConeElsewhere(axis, v, 0.0);
        const double beside = emptyConeElsewhere(square, v, s.r);
        return {std::max(0.0, centre), beside >= 0.0 ? M_PI_2 - beside : M_PI};
    }
    // Your emptyConeAngle() asked about the sphere of radius r at v from the eye, in a frame
    // of its own, new at each call: the eye at a random point, the scene turned by a random
    // rotation and scaled by a random factor. The angles are the same, to rounding (a few
    // ulps, far below any margin an exact cache needs), but nothing it is shown says where the
    // eye or the sphere is: a cache cannot keep the spheres its emptyConeAngle() sees
    double emptyConeElsewhere(const rc::Vec3& axis, const rc::Vec3& v, double r) const {
        const tutorial::Frame rotation = tutorial::randomRotation(frames_);
        auto turn = [&](const rc::Vec3& w) { return rotation.turn(w); };
        const double scale = frames_.logUniform(-2.0, 2.0);
        // Within the scaled distance of the origin, so the translation rounds no worse than the scaling
        const rc::Vec3 apex = frames_.inBox(scale * glm::length(v));
        return tutorial::emptyConeAngle(apex, turn(axis), {rc::Sphere{apex + scale * turn(v), scale * r}});
    }
    const rc::Sphere& sphere(int j) const {
        if (j < 0 || j >= size()) throw std::out_of_range("sphere " + std::to_string(j) + " of " + std::to_string(size()));
        ++tests_;
        return spheres_[j];
    }
    long tests() const { return tests_; }

private:
    const std::vector<rc::Sphere>& spheres_;
    rc::Vec3 eye_;
    mutable long tests_ = 0;
    mutable tutorial::Random frames_;  ///< the frames disc() asks emptyConeAngle() in (seeded per run)
};

// ---- The run's presentation of a scene ------------------------------------------------

// The run's seed: $TUTORIAL_07_SEED when set (to repeat a run), else std::random_device
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_07_SEED");
    return seed;
}

// Said with every failure, so that it can be repeated
std::string seedNote() {
    return " [this run's presentation: TUTORIAL_07_SEED=" + std::to_string(runSeed()) + " repeats it]";
}

// How a cache is shown a scene this run: sphere j is numbered id[j]; a direction d of the
// scene is rotation * d; a sphere (c, r) is (eye + scale * rotation * (c - scene's eye),
// scale * r); the k-th ray asked is that of pixel pixel(k) of the scene's image (scanline
// order of the image flipped left-right, top-bottom and across its diagonal at random, and
// starting at a random row)
struct Presentation {
    std::vector<int> id;
    tutorial::Frame rotation;  // only its rotation: the scale and the eye are below
    double scale = 1.0;
    rc::Vec3 eye{0.0};
    bool flipX = false, flipY = false, transpose = false;
    int firstRow = 0;

    rc::Vec3 turn(const rc::Vec3& v) const { return rotation.turn(v); }
    int shown(int object) const { return object < 0 ? -1 : id[object]; }
    int pixel(int k, int width, int height) const {
        int a = k % width, b = (k / width + firstRow) % height;
        if (transpose) std::swap(a, b);  // square images only
        if (flipX) a = width - 1 - a;
        if (flipY) b = height - 1 - b;
        return b * width + a;
    }
};

Presentation presentation(std::uint64_t seed, int spheres, int width, int height) {
    tutorial::Random rnd(seed);
    Presentation p;
    p.id.resize(spheres);
    for (int j = 0; j < spheres; ++j) p.id[j] = j;
    for (int j = spheres - 1; j > 0; --j) std::swap(p.id[j], p.id[rnd.index(j + 1)]);
    p.rotation = tutorial::randomRotation(rnd);
    p.scale = rnd.logUniform(-1.0, 1.0);
    p.eye = rnd.inBox(10.0);
    p.flipX = rnd.chance(0.5);
    p.flipY = rnd.chance(0.5);
    p.transpose = width == height && rnd.chance(0.5);
    p.firstRow = rnd.index(height);
    return p;
}

// ---- Driving a cache over a scene's eye rays, in the presentation's order ---------------

enum Kind : char { EmptyAnswered, EmptySearched, HitAnswered, HitSearched, Wrong };

// The cost of a cache, in complete searches: the check's own, plus every n tests the
// cache makes in any of its functions. The tests of lookup() and searched() for a ray are
// charged to that ray; those of the constructor to the whole image.
struct Run {
    long rays = 0, emptyRays = 0, emptyBeams = 0;
    long searches = 0, emptySearches = 0;   // complete searches: the check's own, and the lookups of n tests or more
    double cost = 0.0, emptyCost = 0.0;     // complete searches, counting the cache's tests
    long answered = 0, lookupTests = 0, searchedTests = 0, setupTests = 0;
    long renamed = 0;                       // lookups that made n tests or more
    long afterEmpty = 0, afterEmptyAnswered = 0;  // rays that hit a sphere right after an empty one
    int firstWrong = -1, wrongSaid = 0, wrongTruth = 0;  // a pixel of the scene; sphere ids as shown
    long presentationFaults = 0;
    std::vector<char> kind;
    std::vector<int> truth;
    double searchesPerBeam() const { return emptyBeams ? emptyCost / double(emptyBeams) : 0.0; }
    double testsPerAnswer() const {
        if (answered > 0) return double(lookupTests) / double(answered);
        return lookupTests > 0 ? rc::kNoHit : 0.0;
    }
};

struct Scene {
    std::string name;
    int width, height;
    std::vector<rc::Sphere> spheres;
    rc::Camera camera;
    std::vector<int> truth;  ///< the sphere each eye ray hits first, -1 for none (recorded: oracles.h)
};

Scene loadScene(const std::string& name, int size) {
    const rc::Scene s = rc::makeBuiltin(name);
    Scene out{name, size, size, {}, s.camera, {}};
    for (const rc::Object& o : s.objects) out.spheres.push_back(o.bound);
    out.truth = tutorial::eyeHits(out.spheres, out.camera, size, size);
    return out;
}

// `index` numbers the scene among the run's, for a presentation of its own
template <class Make>
Run drive(const Scene& scene, int index, Make make) {
    const rc::RayGenerator camera(scene.camera, scene.width, scene.height);
    const std::uint64_t seed = rc::mixKey(runSeed(), std::uint64_t(index));
    const Presentation shown = presentation(seed, int(scene.spheres.size()), scene.width, scene.height);
    std::vector<rc::Sphere> moved(scene.spheres.size());
    for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
        const rc::Sphere& s = scene.spheres[j];
        moved[shown.id[j]] = {shown.eye + shown.scale * shown.turn(s.c - scene.camera.from), shown.scale * s.r};
    }
    const CountedSpheres spheres(moved, shown.eye, rc::mixKey(seed, 1));
    const double n = double(scene.spheres.size());
    Run run;
    const std::unique_ptr<tutorial::NothingCache> cache = make(spheres);
    run.setupTests = spheres.tests();
    run.cost = double(run.setupTests) / n;
    const int pixels = scene.width * scene.height;
    run.kind.resize(pixels);
    run.truth = scene.truth;  // by the scene's pixels and sphere ids
    int before_truth = -1;    // what the ray asked before hit (its sphere as shown)
    for (int k = 0; k < pixels; ++k) {
        const int p = shown.pixel(k, scene.width, scene.height);
        const rc::Vec3 d = glm::normalize(shown.turn(camera.primary(p % scene.width, p / scene.width).d));
        const int truth = shown.shown(run.truth[p]);
        // The presentation moves no ray across a sphere's edge: the moved spheres the cache
        // measures are hit as the scene's are (else the check, not your cache, is at fault)
        {
            int live = -1;
            double nearest = rc::kNoHit;
            for (int j = 0; j < int(moved.size()); ++j) {
                const double t = rc::intersectSphere(rc::Ray{shown.eye, d}, moved[j], rc::Start::Elsewhere);
                if (t < rc::kNoHit && rc::nearer(t, j, rc::Answer{live, nearest})) live = j, nearest = t;
            }
            if (live != truth) {
                FAIL_CHECK(scene.name << ": the check's presentation moved pixel (" << p % scene.width << ", "
                                      << p / scene.width << ") from sphere " << truth << " to " << live
                                      << ": a fault of the check, not of your cache; please report it" << seedNote());
                ++run.presentationFaults;
            }
        }
        const long before = spheres.tests();
        const tutorial::Known known = cache->lookup(d);
        const long tests = spheres.tests() - before;
        run.lookupTests += tests;
        ++run.rays;
        run.emptyRays += truth < 0;
        // A ray that hits, asked right after one that hit nothing in the same row as shown
        const bool afterEmpty = truth >= 0 && k % scene.width > 0 && before_truth < 0;
        before_truth = truth;
        run.afterEmpty += afterEmpty;
        double cost = double(tests) / n;
        if (known.answered && known.object != truth) {
            run.kind[p] = Wrong;
            if (run.firstWrong < 0) run.firstWrong = p, run.wrongSaid = known.object, run.wrongTruth = truth;
            continue;
        }
        if (known.answered && double(tests) < n) {
            run.kind[p] = truth < 0 ? EmptyAnswered : HitAnswered;
            ++run.answered;
            run.afterEmptyAnswered += afterEmpty;
        } else if (known.answered) {
            // n tests or more: a complete search under another name, counted as one (its
            // tests are already charged to the cost)
            run.kind[p] = truth < 0 ? EmptySearched : HitSearched;
            ++run.renamed;
            ++run.searches;
            run.emptySearches += truth < 0;
        } else {
            run.kind[p] = truth < 0 ? EmptySearched : HitSearched;
            ++run.searches;
            run.emptySearches += truth < 0;
            const long beforeSearched = spheres.tests();
            cache->searched(d, truth);
            run.searchedTests += spheres.tests() - beforeSearched;
            cost += 1.0 + double(spheres.tests() - beforeSearched) / n;
        }
        run.cost += cost;
        if (truth < 0) run.emptyCost += cost;
    }
    run.emptyBeams = tutorial::emptyBeams(scene.width, scene.height, run.truth);
    return run;
}

// The picture: spheres in their colours (lighter where the cache answered), empty rays
// blue where the cache answered and red where they needed a complete search, magenta
// where the cache gave a wrong answer
std::string draw(const Scene& scene, const Run& run, const std::string& name) {
    tutorial::Picture pic(scene.width, scene.height);
    for (int p = 0; p < scene.width * scene.height; ++p) {
        tutorial::Rgb c;
        switch (run.kind[p]) {
            case EmptyAnswered: c = {40, 70, 150}; break;
            case EmptySearched: c = {230, 40, 30}; break;
            case HitAnswered: c = tutorial::labelColour(run.truth[p]); break;
            case HitSearched: c = tutorial::shade(tutorial::labelColour(run.truth[p]), 0.45); break;
            default: c = {255, 0, 255}; break;
        }
        pic.set(p % scene.width, p / scene.width, c);
    }
    return pic.save(name, 4);
}

std::vector<Scene> scenes() { return {loadScene("cube:4", 96), loadScene("cube:6", 96), loadScene("pair", 96)}; }


// A lookup that tests every sphere is a complete search under another name: the tests
// the lookups make, per ray they answer, may be at most a tenth of the spheres, or 1,
// whichever is more: fewer than every sphere on every scene, pair's 2 included. (And a
// lookup that makes n tests or more is not an answer at all: see drive().)
constexpr double kListFraction = 0.1;
double maxTestsPerAnswer(const Scene& scene) { return std::max(1.0, kListFraction * double(scene.spheres.size())); }

// Challenge thresholds. For the reference solution the check makes 0.07-0.11 times the
// complete searches on empty rays that it makes for the one-cone cache; counting the
// cache's own tests, it costs 0.28-0.71 times the one-cone cache in all, and it answers
// 69-97% of the rays after an empty one (over twenty presentations: TUTORIAL_07_SEED=1..10
// and ten from std::random_device; see the instructor's answers).
constexpr double kChallengeSearchFraction = 0.2;  // of the one-empty-cone cache's searches on empty rays
constexpr double kChallengeAfterEmpty = 0.5;      // rays after an empty ray answered by the cache

// The yardstick of the challenge (tutorial::oneCone, data: oracles.h, oracle_data.txt)
tutorial::OneCone oneCone(const Scene& scene) {
    return tutorial::oneCone(scene.spheres, scene.camera, scene.width, scene.height);
}

void printRow(const char* cache, const Run& r) {
    std::printf("  %-20s %9.1f %9.1f %8.2f %9ld %9ld %12.2f %7ld/%ld\n", cache, r.cost, r.emptyCost, r.searchesPerBeam(),
                r.searches, r.setupTests + r.lookupTests + r.searchedTests, r.testsPerAnswer(), r.afterEmptyAnswered,
                r.afterEmpty);
}

}  // namespace

// Grades the three parts at the end of the run
struct GradeReport : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testCaseEnded(const Catch::TestCaseStats& stats) override {
        grades.emplace_back(stats.testInfo.name, stats.totals.assertions.failed == 0);
    }
    void testRunEnded(const Catch::TestRunStats&) override {
        std::printf("\nTutorial 07, graded parts:\n");
        for (const auto& [name, passed] : grades)
            std::printf("  %-8s %s\n", passed ? "passed" : "not yet", name.c_str());
    }
    std::vector<std::pair<std::string, bool>> grades;
};
CATCH_REGISTER_LISTENER(GradeReport)

TEST_CASE("basic: emptyConeAngle is the widest empty cone, and no ray inside it hits", "[tutorial07]") {
    // Each case shown in a frame of the run's own: the spheres in a shuffled order, the
    // apex, axis and spheres rotated, moved (up to 10) and scaled by a power of two, which
    // keeps every angle. The rotation rounds the coordinates by some 1e-14, which moves an
    // angle by that over the apex's distance to a sphere: far inside the tolerance
    INFO("each case is shown to your code renumbered, rotated, moved and scaled; the numbers below are the case's own"
         << seedNote());
    tutorial::Random rnd(1986), frames(rc::mixKey(runSeed(), 1986));
    int open = 0, closed = 0;
    for (int i = 0; i < 4000; ++i) {
        std::vector<rc::Sphere> spheres(i % 50 == 0 ? 0 : 1 + rnd.index(20));
        for (rc::Sphere& s : spheres) s = {rnd.inBox(10.0), rnd.logUniform(-2.0, 0.3)};
        const rc::Vec3 apex = rnd.inBox(12.0);
        const rc::Sphere aimAt = spheres.empty() ? rc::Sphere{} : spheres[rnd.index(int(spheres.size()))];
        // Sometimes straight at a sphere, usually anywhere
        const rc::Vec3 axis = !spheres.empty() && i % 5 == 0
                                  ? glm::normalize(aimAt.c + 0.5 * aimAt.r * rnd.inBox(1.0) - apex)
                                  : rnd.direction();
        const double want = coneAngle(apex, axis, spheres);
        const tutorial::Frame frame = tutorial::randomFrame(frames, 10.0, 4);
        std::vector<rc::Sphere> moved;
        for (const rc::Sphere& s : spheres) moved.push_back(frame.sphere(s));
        for (int k = int(moved.size()) - 1; k > 0; --k) std::swap(moved[k], moved[frames.index(k + 1)]);
        const rc::Vec3 shownApex = frame.point(apex), shownAxis = frame.turn(axis);
        const double got = tutorial::emptyConeAngle(shownApex, shownAxis, moved);
        INFO(std::setprecision(17) << "case " << i << ": " << spheres.size() << " spheres, apex (" << apex.x << ", " << apex.y << ", "
                     << apex.z << "); expected " << want << ", yours " << got);
        if (std::isinf(want)) {
            INFO(std::setprecision(17) << "no sphere at all: every direction is empty (rc::kNoHit)");
            REQUIRE(std::isinf(got));
        } else if (want < 0.0) {
            INFO(std::setprecision(17) << "the ray along the axis meets a sphere (or the apex is inside one): no empty cone");
            REQUIRE(got < 0.0);
            ++closed;
        } else {
            REQUIRE(std::abs(got - want) <= 1e-9 * std::max(1.0, want));
            // Rays on the cone's edge, just inside: none may hit
            // (in the frame your code was shown)
            const rc::Vec3 side = glm::normalize(glm::cross(shownAxis, rnd.direction()));
            for (int k = 0; k < 8; ++k) {
                const double a = std::min(got, M_PI) * (1.0 - 1e-7), turn = 2.0 * M_PI * k / 8.0;
                const rc::Vec3 ortho = std::cos(turn) * side + std::sin(turn) * glm::cross(shownAxis, side);
                const rc::Ray ray{shownApex, glm::normalize(std::cos(a) * shownAxis + std::sin(a) * ortho)};
                INFO(std::setprecision(17) << "a ray " << a << " radians from the axis meets sphere " << anyMet(ray, moved)
                                           << " (numbered as your code was shown them)");
                REQUIRE(anyMet(ray, moved) < 0);
            }
            ++open;
        }
    }
    CHECK(open > 1000);
    CHECK(closed > 500);
}

TEST_CASE("intermediate: your cache is exact, cheap, and beats the cylinder of safety on rays that hit nothing",
          "[tutorial07]") {
    std::printf("\nComplete searches on the eye rays (96x96, in this run's order), counting every n tests a cache\n"
                "makes (n spheres, in any of its functions) as one more.%s\n", seedNote().c_str());
    INFO("Each scene is shown to your cache renumbered, moved and asked in an order of this run's own" << seedNote());
    const std::vector<Scene> all = scenes();
    for (int index = 0; index < int(all.size()); ++index) {
        const Scene& scene = all[index];
        const double n = double(scene.spheres.size());
        const tutorial::CylinderRow cylinder = tutorial::cylinderRow(scene.spheres, scene.camera, scene.width, scene.height);
        const tutorial::OneCone cone = oneCone(scene);
        const Run yours = drive(scene, index, [](const CountedSpheres& s) { return tutorial::makeNothingCache(s); });
        std::printf("%s: %zu spheres, %ld eye rays, %ld hit nothing, in %ld beam(s)\n", scene.name.c_str(),
                    scene.spheres.size(), yours.rays, yours.emptyRays, yours.emptyBeams);
        std::printf("  %-20s %9s %9s %8s %9s %9s %12s %13s\n", "cache", "searches", "on empty", "per beam", "by check",
                    "its tests", "tests/answer", "after empty");
        std::printf("  %-20s %9ld %9ld %8.2f %9ld %9d %12s %13s\n", "none", yours.rays, yours.emptyRays,
                    double(yours.emptyRays) / double(std::max(1L, yours.emptyBeams)), yours.rays, 0, "-", "-");
        std::printf("  %-20s %9.1f %9.1f %8.2f %9ld %9ld %12.2f %7ld/%ld\n", "cylinder of safety", cylinder.cost,
                    cylinder.emptyCost, cylinder.searchesPerBeam, cylinder.searches, cylinder.tests, cylinder.testsPerAnswer,
                    cylinder.afterEmptyAnswered, cylinder.afterEmpty);
        std::printf("  %-20s %9.1f %9.1f\n", "one empty cone", cone.cost, 2.0 * double(cone.emptySearches));
        printRow("yours", yours);
        const std::string path = draw(scene, yours, scene.name == "cube:4" ? "cube4" : scene.name == "cube:6" ? "cube6" : scene.name);
        tutorial::announcePicture("your cache on " + scene.name + ": blue answered, red searched, magenta wrong", path);
        // Every scene is graded (CHECK), so a failure names each scene it fails on
        if (yours.firstWrong >= 0) {
            FAIL_CHECK(scene.name << ": pixel (" << yours.firstWrong % scene.width << ", " << yours.firstWrong / scene.width
                                  << "): your cache answered sphere " << yours.wrongSaid << " (-1: nothing), the complete search finds "
                                  << yours.wrongTruth << " (numbered as your cache was shown them). Wrong pixels are magenta in "
                                  << path << seedNote());
            continue;
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your cache costs " << yours.emptyCost
                                       << " complete searches on rays that hit nothing (" << yours.emptySearches
                                       << " made by the check or by lookups of n tests or more, the rest your cache's tests / " << n
                                       << "); the cylinder of safety costs " << cylinder.emptyCost << ". Red pixels in " << path);
            CHECK(yours.emptyCost < cylinder.emptyCost);
        }
        {
            // A bar of its own, beside the cylinder's: a cache must answer most of the rays
            // that hit nothing
            INFO(std::setprecision(17) << scene.name << ": your cache costs " << yours.emptyCost
                                       << " complete searches on rays that hit nothing; no cache at all costs "
                                       << yours.emptyRays << ", and a cache must cost at most three quarters of that, "
                                       << 0.75 * double(yours.emptyRays) << " (one empty cone: " << 2.0 * double(cone.emptySearches)
                                       << "). Red pixels in " << path);
            CHECK(yours.emptyCost <= 0.75 * double(yours.emptyRays));
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your cache costs " << yours.cost << " complete searches in all ("
                                       << yours.searches << " made by the check or by a lookup, " << yours.renamed
                                       << " of them lookups of n tests or more, " << yours.setupTests + yours.lookupTests + yours.searchedTests
                                       << " tests of your cache in all: " << yours.setupTests << " in the constructor, "
                                       << yours.lookupTests << " in lookup(), " << yours.searchedTests
                                       << " in searched()); the cylinder of safety costs " << cylinder.cost);
            CHECK(yours.cost < cylinder.cost);
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your lookups make " << yours.lookupTests << " tests for the "
                                       << yours.answered << " rays they answer, " << yours.testsPerAnswer()
                                       << " per answer; a complete search tests " << n << ", and at most "
                                       << maxTestsPerAnswer(scene) << " counts as a cache");
            CHECK(yours.testsPerAnswer() <= maxTestsPerAnswer(scene));
        }
    }
}

TEST_CASE("challenge: a fifth of the one-cone cache's complete searches on rays that hit nothing, cheaply",
          "[tutorial07]") {
    INFO("Each scene is shown to your cache renumbered, moved and asked in an order of this run's own" << seedNote());
    const std::vector<Scene> all = scenes();
    for (int index = 0; index < int(all.size()); ++index) {
        const Scene& scene = all[index];
        const tutorial::OneCone cone = oneCone(scene);
        const Run yours = drive(scene, index, [](const CountedSpheres& s) { return tutorial::makeNothingCache(s); });
        if (yours.firstWrong >= 0) {
            FAIL_CHECK(scene.name << ": a wrong answer at pixel (" << yours.firstWrong % scene.width << ", "
                                  << yours.firstWrong / scene.width << ")" << seedNote());
            continue;
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your cache needed " << yours.emptySearches
                                       << " complete searches on rays that hit nothing (the check's, and its lookups of n tests or more); the check made "
                                       << cone.emptySearches << " for the one-empty-cone cache, and the challenge asks for at most "
                                       << kChallengeSearchFraction << " of that");
            CHECK(double(yours.emptySearches) <= kChallengeSearchFraction * double(cone.emptySearches));
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your cache costs " << yours.cost
                                       << " complete searches in all, counting its own tests (" << yours.searches
                                       << " made by the check or by a lookup, " << yours.renamed << " of them lookups of n tests or more, "
                                       << yours.setupTests + yours.lookupTests + yours.searchedTests
                                       << " tests of your cache / " << scene.spheres.size()
                                       << "); the one-empty-cone cache costs " << cone.cost);
            CHECK(yours.cost < cone.cost);
        }
        {
            INFO(std::setprecision(17) << scene.name << ": your lookups make " << yours.testsPerAnswer()
                                       << " tests per answer, at most " << maxTestsPerAnswer(scene) << " allowed");
            CHECK(yours.testsPerAnswer() <= maxTestsPerAnswer(scene));
        }
        {
            INFO(std::setprecision(17) << scene.name << ": of " << yours.afterEmpty
                                       << " rays that hit a sphere right after a ray that hit nothing, your cache answered "
                                       << yours.afterEmptyAnswered << "; the challenge asks for half");
            CHECK(double(yours.afterEmptyAnswered) >= kChallengeAfterEmpty * double(yours.afterEmpty));
        }
    }
}
