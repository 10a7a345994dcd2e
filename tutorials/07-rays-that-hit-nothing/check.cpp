// Tutorial 07's check, in three graded parts:
//   basic         emptyConeAngle against the formula, and no ray inside the cone hits
//   intermediate  the cache is exact on every eye ray of three scenes, makes fewer
//                 complete searches on rays that hit nothing than the cylinder of safety,
//                 and its lookups are cheap (a few sphere tests per answer, not a search)
//   challenge     a fifth of the one-empty-cone cache's complete searches on rays that
//                 hit nothing, still cheap, and rays that follow an empty ray answered too
// It prints the measurement the student reports (complete searches per beam) beside
// the no-cache, cylinder-of-safety and one-empty-cone caches the check runs itself, and
// draws the student's cache at work as a PNG.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

// The grade report is a Catch2 event listener
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include "exercise.h"
#include "geometry/safety_cylinder.h"
#include "scene/builtin_scenes.h"
#include "search/query.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {

double angleBetween(const rc::Vec3& a, const rc::Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The check's own empty cone: the same definition, written independently
double coneAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres) {
    double angle = rc::kNoHit;
    for (const rc::Sphere& s : spheres) {
        const double dist = glm::length(s.c - apex);
        if (dist <= s.r) return -1.0;
        angle = std::min(angle, angleBetween(axis, s.c - apex) - std::asin(s.r / dist));
    }
    return angle;
}

// The complete search: the nearest sphere the ray hits, ties to the lower index
int nearest(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres) {
    rc::Answer best;
    for (int j = 0; j < int(spheres.size()); ++j) {
        const double t = rc::intersectSphere(ray, spheres[j], rc::Start::Elsewhere);
        if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
    }
    return best.object;
}

// ---- The caches the check runs itself, for comparison ---------------------------------

// Speer, DeRose and Barsky's cylinder for a ray that hits nothing: the segment from the
// eye to where it leaves the scene's bounding sphere, as thick as the gap to the nearest sphere
class CylinderCache final : public tutorial::NothingCache {
public:
    CylinderCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) : spheres_(spheres), eye_(eye) {
        for (const rc::Sphere& s : spheres) bound_.c += s.c / double(spheres.size());
        for (const rc::Sphere& s : spheres) bound_.r = std::max(bound_.r, glm::length(s.c - bound_.c) + s.r);
    }
    tutorial::Known lookup(const rc::Vec3& d, long&) override {
        if (!(radius_ > 0.0)) return {};
        const rc::Vec3 end = segmentEnd(d);
        if (rc::segmentDistance(end, eye_, end_) <= radius_) return {true, -1};
        return {};
    }
    void searched(const rc::Vec3& d, int object) override {
        if (object >= 0) return;
        end_ = segmentEnd(d);
        radius_ = rc::kNoHit;
        for (const rc::Sphere& s : spheres_) radius_ = std::min(radius_, rc::segmentDistance(s.c, eye_, end_) - s.r);
        radius_ *= 1.0 - 1e-12;
    }

private:
    // Where the ray leaves the bounding sphere; its nearest point to the centre if it misses it
    rc::Vec3 segmentEnd(const rc::Vec3& d) const {
        const rc::Ray ray{eye_, d};
        const rc::SphereRoots roots = rc::sphereRootsStable(ray, bound_);
        return ray.at(roots.hit && roots.t1 > 0.0 ? roots.t1 : std::max(0.0, glm::dot(bound_.c - eye_, d)));
    }
    std::vector<rc::Sphere> spheres_;
    rc::Vec3 eye_;
    rc::Sphere bound_{rc::Vec3{0.0}, 0.0};
    rc::Vec3 end_{0.0};
    double radius_ = -1.0;
};

// The design notes' one exact answer: the empty cone of the last ray that hit nothing
class OneConeCache final : public tutorial::NothingCache {
public:
    OneConeCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) : spheres_(spheres), eye_(eye) {}
    tutorial::Known lookup(const rc::Vec3& d, long&) override {
        if (angle_ > 0.0 && angleBetween(axis_, d) < angle_ * (1.0 - 1e-9)) return {true, -1};
        return {};
    }
    void searched(const rc::Vec3& d, int object) override {
        if (object >= 0) return;
        axis_ = d;
        angle_ = coneAngle(eye_, d, spheres_);
    }

private:
    std::vector<rc::Sphere> spheres_;
    rc::Vec3 eye_, axis_{0.0};
    double angle_ = -1.0;
};

// ---- Driving a cache over a scene's eye rays in scanline order ------------------------

enum Kind : char { EmptyAnswered, EmptySearched, HitAnswered, HitSearched, Wrong };

struct Run {
    long rays = 0, emptyRays = 0, emptyBeams = 0, emptySearches = 0;
    long searches = 0, lookupTests = 0;
    long afterEmpty = 0, afterEmptyAnswered = 0;  // rays that hit a sphere right after an empty one
    int firstWrong = -1, wrongSaid = 0, wrongTruth = 0;
    std::vector<char> kind;
    std::vector<int> truth;
    double searchesPerBeam() const { return emptyBeams ? double(emptySearches) / double(emptyBeams) : 0.0; }
};

struct Scene {
    std::string name;
    int width, height;
    std::vector<rc::Sphere> spheres;
    rc::Camera camera;
};

Scene loadScene(const std::string& name, int size) {
    const rc::Scene s = rc::makeBuiltin(name);
    Scene out{name, size, size, {}, s.camera};
    for (const rc::Object& o : s.objects) out.spheres.push_back(o.bound);
    return out;
}

// 4-connected pieces of pixels whose rays hit nothing: the beams of empty eye rays
long countBeams(int width, int height, const std::vector<int>& truth) {
    std::vector<char> seen(truth.size(), 0);
    std::vector<int> stack;
    long beams = 0;
    for (int p = 0; p < width * height; ++p) {
        if (truth[p] >= 0 || seen[p]) continue;
        ++beams;
        seen[p] = 1;
        stack.push_back(p);
        while (!stack.empty()) {
            const int q = stack.back();
            stack.pop_back();
            const int x = q % width, y = q / width;
            for (const int r : {x > 0 ? q - 1 : -1, x + 1 < width ? q + 1 : -1, y > 0 ? q - width : -1,
                                y + 1 < height ? q + width : -1})
                if (r >= 0 && truth[r] < 0 && !seen[r]) seen[r] = 1, stack.push_back(r);
        }
    }
    return beams;
}

template <class Make>
Run drive(const Scene& scene, Make make) {
    const rc::RayGenerator camera(scene.camera, scene.width, scene.height);
    const std::unique_ptr<tutorial::NothingCache> cache = make(scene.spheres, scene.camera.from);
    Run run;
    const int n = scene.width * scene.height;
    run.kind.resize(n);
    run.truth.resize(n);
    for (int p = 0; p < n; ++p) run.truth[p] = nearest(camera.primary(p % scene.width, p / scene.width), scene.spheres);
    for (int p = 0; p < n; ++p) {
        const rc::Ray ray = camera.primary(p % scene.width, p / scene.width);
        const int truth = run.truth[p];
        long tests = 0;
        const tutorial::Known known = cache->lookup(ray.d, tests);
        run.lookupTests += tests;
        ++run.rays;
        run.emptyRays += truth < 0;
        const bool afterEmpty = truth >= 0 && p % scene.width > 0 && run.truth[p - 1] < 0;
        run.afterEmpty += afterEmpty;
        if (known.answered) {
            if (known.object != truth) {
                run.kind[p] = Wrong;
                if (run.firstWrong < 0) run.firstWrong = p, run.wrongSaid = known.object, run.wrongTruth = truth;
                continue;
            }
            run.kind[p] = truth < 0 ? EmptyAnswered : HitAnswered;
            run.afterEmptyAnswered += afterEmpty;
        } else {
            run.kind[p] = truth < 0 ? EmptySearched : HitSearched;
            ++run.searches;
            run.emptySearches += truth < 0;
            cache->searched(ray.d, truth);
        }
    }
    run.emptyBeams = countBeams(scene.width, scene.height, run.truth);
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
// your lookups make, per ray they answer, may be at most a tenth of the spheres, or 1,
// whichever is more: fewer than every sphere on every scene, pair's 2 included.
constexpr double kListFraction = 0.1;
double maxTestsPerAnswer(const Scene& scene) { return std::max(1.0, kListFraction * double(scene.spheres.size())); }
double testsPerAnswer(const Run& r) {
    const long answered = r.rays - r.searches;
    return answered > 0 ? double(r.lookupTests) / double(answered) : 0.0;
}

// Challenge thresholds. The reference solution makes 0.07 times the one-cone cache's
// complete searches on empty rays, and answers 87-94% of the rays after an empty one
// (see the instructor's answers).
constexpr double kChallengeSearchFraction = 0.2;  // of the one-empty-cone cache's searches on empty rays
constexpr double kChallengeAfterEmpty = 0.5;      // rays after an empty ray answered by the cache

void printRow(const char* cache, const Run& r) {
    std::printf("  %-22s %9ld %9ld %8.2f %10.2f %11ld/%ld\n", cache, r.searches, r.emptySearches, r.searchesPerBeam(),
                testsPerAnswer(r), r.afterEmptyAnswered, r.afterEmpty);
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
    tutorial::Random rnd(1986);
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
        const double got = tutorial::emptyConeAngle(apex, axis, spheres);
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
            const rc::Vec3 side = glm::normalize(glm::cross(axis, rnd.direction()));
            for (int k = 0; k < 8; ++k) {
                const double a = std::min(got, M_PI) * (1.0 - 1e-7), turn = 2.0 * M_PI * k / 8.0;
                const rc::Vec3 ortho = std::cos(turn) * side + std::sin(turn) * glm::cross(axis, side);
                const rc::Ray ray{apex, glm::normalize(std::cos(a) * axis + std::sin(a) * ortho)};
                INFO(std::setprecision(17) << "a ray " << a << " radians from the axis hits sphere " << nearest(ray, spheres));
                REQUIRE(nearest(ray, spheres) < 0);
            }
            ++open;
        }
    }
    CHECK(open > 1000);
    CHECK(closed > 500);
}

TEST_CASE("intermediate: your cache is exact, cheap, and beats the cylinder of safety on rays that hit nothing",
          "[tutorial07]") {
    std::printf("\nComplete searches on the eye rays (scanline order, 96x96):\n");
    for (const Scene& scene : scenes()) {
        const Run cylinder = drive(scene, [](const auto& s, const auto& e) { return std::make_unique<CylinderCache>(s, e); });
        const Run cone = drive(scene, [](const auto& s, const auto& e) { return std::make_unique<OneConeCache>(s, e); });
        const Run yours = drive(scene, tutorial::makeNothingCache);
        std::printf("%s: %zu spheres, %ld eye rays, %ld hit nothing, in %ld beam(s)\n", scene.name.c_str(),
                    scene.spheres.size(), yours.rays, yours.emptyRays, yours.emptyBeams);
        std::printf("  %-22s %9s %9s %8s %10s %13s\n", "cache", "searches", "on empty", "per beam", "tests/answer",
                    "after empty");
        std::printf("  %-22s %9ld %9ld %8.2f %10s %13s\n", "none", yours.rays, yours.emptyRays,
                    double(yours.emptyRays) / double(std::max(1L, yours.emptyBeams)), "-", "-");
        printRow("cylinder of safety", cylinder);
        printRow("one empty cone", cone);
        printRow("yours", yours);
        const std::string path = draw(scene, yours, scene.name == "cube:4" ? "cube4" : scene.name == "cube:6" ? "cube6" : scene.name);
        tutorial::announcePicture("your cache on " + scene.name + ": blue answered, red searched, magenta wrong", path);
        if (yours.firstWrong >= 0)
            FAIL(std::setprecision(17) << scene.name << ": pixel (" << yours.firstWrong % scene.width << ", "
                                       << yours.firstWrong / scene.width << "): your cache answered " << yours.wrongSaid
                                       << " (-1: nothing), the complete search finds " << yours.wrongTruth
                                       << ". Wrong pixels are magenta in " << path);
        INFO(std::setprecision(17) << scene.name << ": your cache made " << yours.emptySearches
                        << " complete searches on rays that hit nothing; the cylinder of safety makes "
                        << cylinder.emptySearches << ". Red pixels in " << path);
        REQUIRE(yours.emptySearches < cylinder.emptySearches);
        INFO(std::setprecision(17) << scene.name << ": your lookups test " << testsPerAnswer(yours) << " spheres per ray they answer; a "
                        << "complete search tests " << scene.spheres.size() << ", and at most "
                        << maxTestsPerAnswer(scene) << " counts as a cache");
        REQUIRE(testsPerAnswer(yours) <= maxTestsPerAnswer(scene));
    }
}

TEST_CASE("challenge: a fifth of the one-cone cache's complete searches on rays that hit nothing, cheaply",
          "[tutorial07]") {
    for (const Scene& scene : scenes()) {
        const Run cone = drive(scene, [](const auto& s, const auto& e) { return std::make_unique<OneConeCache>(s, e); });
        const Run yours = drive(scene, tutorial::makeNothingCache);
        REQUIRE(yours.firstWrong < 0);
        INFO(std::setprecision(17) << scene.name << ": " << yours.emptySearches << " complete searches on rays that hit nothing ("
                        << yours.searchesPerBeam() << " per beam); the one-empty-cone cache makes " << cone.emptySearches
                        << ", the challenge asks for at most " << kChallengeSearchFraction << " of that");
        REQUIRE(double(yours.emptySearches) <= kChallengeSearchFraction * double(cone.emptySearches));
        REQUIRE(testsPerAnswer(yours) <= maxTestsPerAnswer(scene));
        INFO(std::setprecision(17) << scene.name << ": of " << yours.afterEmpty << " rays that hit a sphere right after a ray that hit nothing, "
                        << "your cache answered " << yours.afterEmptyAnswered << "; the challenge asks for half");
        REQUIRE(double(yours.afterEmptyAnswered) >= kChallengeAfterEmpty * double(yours.afterEmpty));
    }
}
