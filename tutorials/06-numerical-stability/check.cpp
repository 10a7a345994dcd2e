// Tutorial 06's check: rc::sphereRootsStable and rc::stableQuadraticRoots (your
// tutorials/06-numerical-stability/exercise.cpp in a student build) against independent oracles:
// quadratics built from known roots, and roots found by bisection in long double
// and polished in quad precision (its answers are data: oracles.h, oracle_data.txt), on ordinary cases (where the textbook
// formula is fine too) and on stiff ones (where it is not).
//
// Each run shows your roots every recorded ray and sphere in a frame of its own
// (tutorial_frame.h): rotated, moved and scaled by a power of two (on the exact-integer
// cases, turned by a random signed permutation of the axes and moved by whole units, so that
// they stay exact), drawn from a seed (std::random_device, or $TUTORIAL_06_SEED to repeat a
// run; failures print it). The ray's direction keeps its length, so an expected root is the
// recorded one times the scale.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "scene/nff_reader.h"
#include "search/query.h"
#include "oracles.h"
#include "tutorial_frame.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace {

// A ray towards the sphere, its closest approach `aim` radii from the centre
rc::Ray rayTowards(tutorial::Random& rnd, const rc::Sphere& s, double distance, double aim) {
    const rc::Vec3 o = s.c + distance * rnd.direction();
    // A direction at perpendicular offset aim * r from the centre
    const rc::Vec3 axis = glm::normalize(s.c - o);
    rc::Vec3 side = glm::cross(axis, rnd.direction());
    side = glm::normalize(side);
    const rc::Vec3 target = s.c + aim * s.r * side;
    return {o, glm::normalize(target - o)};
}

// The run's seed, said with every failure so that the run can be repeated
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_06_SEED");
    return seed;
}
std::string seedNote() {
    return " [this run's frames: TUTORIAL_06_SEED=" + std::to_string(runSeed()) + " repeats them]";
}

// Your roots in the frame `f`, brought back to the case's units (the scale is a power of
// two: dividing by it rounds nothing)
rc::SphereRoots yours(const tutorial::Frame& f, const rc::Ray& ray, const rc::Sphere& s) {
    rc::SphereRoots r = rc::sphereRootsStable(f.ray(ray), f.sphere(s));
    r.t0 /= f.scale, r.t1 /= f.scale;
    return r;
}

// A frame that rounds nothing on integer coordinates below 2^40: the axes permuted and
// flipped, a shift of whole units up to 1000, a scale 2^k, |k| <= 4
tutorial::Frame exactFrame(tutorial::Random& rnd) {
    tutorial::Frame f;
    rc::Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 2; k > 0; --k) std::swap(axes[k], axes[rnd.index(k + 1)]);
    for (rc::Vec3& a : axes)
        if (rnd.chance(0.5)) a = -a;
    f.x = axes[0], f.y = axes[1], f.z = axes[2];
    f.shift = {std::round(rnd.uniform(-1000, 1000)), std::round(rnd.uniform(-1000, 1000)),
               std::round(rnd.uniform(-1000, 1000))};
    f.scale = std::ldexp(1.0, rnd.index(9) - 4);
    return f;
}

// The oracle's roots, rounded to doubles
rc::SphereRoots oracle(const rc::Ray& ray, const rc::Sphere& s) { return tutorial::oracleSphereRoots(ray, s); }

// Your roots must match the oracle's to 1e-12 of the problem's size. The frame shifts by at
// most the problem's size (`reach`), so its rotation rounds the coordinates your roots see
// by a few ulps of it, some 1e-15 of the size: the tolerance holds them 100 times over
void compare(tutorial::Random& frames, const rc::Ray& ray, const rc::Sphere& s, double aim) {
    const rc::SphereRoots want = oracle(ray, s);
    const double reach = std::max({glm::length(ray.o), glm::length(s.c), s.r});
    const rc::SphereRoots got = yours(tutorial::randomFrame(frames, reach, 4), ray, s);
    INFO("the ray and sphere are shown to your code rotated, moved and scaled" << seedNote());
    INFO(std::setprecision(17) << "sphere radius " << s.r << " at distance " << glm::length(s.c - ray.o) << ", aimed " << aim
                          << " radii off centre; library: hit " << want.hit << " t0 " << want.t0 << " t1 "
                          << want.t1 << "; yours: hit " << got.hit << " t0 " << got.t0 << " t1 " << got.t1);
    // Near tangency either answer is defensible; elsewhere the hit must agree
    if (aim < 0.9 || aim > 1.1) REQUIRE(got.hit == want.hit);
    if (!got.hit || !want.hit) return;
    // Any formula is limited by the rounding of the coordinates, which are as large as
    // the distance to the centre and the radius: measure the error against those
    const double scale = std::max({1.0, std::abs(want.t0), std::abs(want.t1), glm::length(ray.o - s.c), s.r});
    REQUIRE(std::abs(got.t0 - want.t0) <= 1e-12 * scale);
    REQUIRE(std::abs(got.t1 - want.t1) <= 1e-12 * scale);
}

}  // namespace

TEST_CASE("stableRoots agrees with the oracle on ordinary spheres", "[tutorial06]") {
    tutorial::Random rnd(7), frames(rc::mixKey(runSeed(), 1));
    for (int i = 0; i < 2000; ++i) {
        const rc::Sphere s{rnd.inBox(10.0), rnd.uniform(0.5, 3.0)};
        const double aim = rnd.uniform(0.0, 1.5);
        compare(frames, rayTowards(rnd, s, rnd.uniform(4.0, 30.0), aim), s, aim);
    }
}

TEST_CASE("stableRoots agrees with the oracle on small spheres far away", "[tutorial06]") {
    // The textbook formula forms b*b - c from two numbers near distance^2 and loses
    // every digit of r^2 once r^2 is below distance^2 times the double's epsilon
    tutorial::Random rnd(2020), frames(rc::mixKey(runSeed(), 2));
    for (int i = 0; i < 2000; ++i) {
        const rc::Sphere s{rnd.inBox(1.0), rnd.logUniform(-4.0, -1.0)};
        const double aim = rnd.uniform(0.0, 0.85);  // a clear hit
        compare(frames, rayTowards(rnd, s, rnd.logUniform(3.0, 7.0), aim), s, aim);
    }
}

TEST_CASE("stableRoots agrees with the oracle from inside and on the surface", "[tutorial06]") {
    tutorial::Random rnd(1986), frames(rc::mixKey(runSeed(), 3));
    for (int i = 0; i < 2000; ++i) {
        const rc::Sphere s{rnd.inBox(10.0), rnd.logUniform(-2.0, 3.0)};
        // The origin inside the sphere, or on its surface (a ray leaving a hit point, not
        // grazing: near tangency every formula loses digits to the rounding of the origin)
        const double at = i % 2 ? rnd.uniform(0.0, 0.99) : 1.0;
        const rc::Vec3 n = rnd.direction();
        rc::Vec3 d = rnd.direction();
        while (at == 1.0 && std::abs(glm::dot(d, n)) < 0.1) d = rnd.direction();
        compare(frames, rc::Ray{s.c + at * s.r * n, d}, s, 0.0);
    }
}

TEST_CASE("stableRoots keeps the near root's relative accuracy just outside a large sphere", "[tutorial06]") {
    // Integer coordinates, so the offset f and c = |f|^2 - r^2 are exact: an origin a
    // little outside a large sphere, where the near root is tiny and -b - sqrt(disc)
    // subtracts two nearly equal numbers. Only t0 = c / q (Vieta) keeps its digits.
    INFO("the ray and sphere are shown to your code with their axes permuted and flipped, moved by whole units and "
         "scaled by a power of two" << seedNote());
    tutorial::Random rnd(1986), frames(rc::mixKey(runSeed(), 4));
    for (int i = 0; i < 2000; ++i) {
        const double r = std::round(rnd.logUniform(3.0, 6.0));
        const rc::Vec3 c{std::round(rnd.uniform(-100, 100)), std::round(rnd.uniform(-100, 100)),
                         std::round(rnd.uniform(-100, 100))};
        // f = (r, m, n) with its axes permuted and signs flipped: |f|^2 - r^2 = m^2 + n^2
        double f[3] = {r, double(1 + rnd.index(20)), double(rnd.index(20))};
        std::swap(f[0], f[rnd.index(3)]);
        for (double& x : f)
            if (rnd.chance(0.5)) x = -x;
        const rc::Vec3 o = c + rc::Vec3{f[0], f[1], f[2]};
        const rc::Sphere s{c, r};
        // Aim at a point well inside the sphere: a clear hit, the near root tiny
        const rc::Ray ray{o, glm::normalize(c + 0.5 * r * rnd.direction() - o)};
        const rc::SphereRoots want = oracle(ray, s);
        const rc::SphereRoots got = yours(exactFrame(frames), ray, s);
        INFO(std::setprecision(17) << "sphere radius " << r << ", origin " << std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) - r
                              << " outside it; oracle t0 " << want.t0 << ", yours " << got.t0 << " (relative error "
                              << std::abs(got.t0 - want.t0) / want.t0 << ")");
        REQUIRE(want.hit);
        REQUIRE(got.hit);
        // The near root to 1e-12 of itself: the subtraction -b - sqrt(disc) loses
        // about r / t0 units in the last place, up to a million here
        REQUIRE(std::abs(got.t0 - want.t0) <= 1e-12 * want.t0);
        REQUIRE(std::abs(got.t1 - want.t1) <= 1e-12 * want.t1);
    }
}

TEST_CASE("stableQuadraticRoots finds both roots of quadratics whose roots are known", "[tutorial06]") {
    // a (t - near)(t - far) = a t^2 + 2 h t + c, with disc = h^2 - a c = (a (far - near) / 2)^2:
    // the roots are known without solving anything. a, near and far have few bits, so h, c
    // and disc are rounded at most twice each, which moves each root by a few units in the
    // last place. far is up to 2^62 times near: the textbook's near root loses that many.
    tutorial::Random rnd(6);
    for (int i = 0; i < 2000; ++i) {
        const double a = double(1 + rnd.index(16)) * (rnd.chance(0.5) ? 1.0 : -1.0);
        const double near = std::ldexp(double(1 + rnd.index(1024)), -int(rnd.index(21))) * (rnd.chance(0.5) ? 1.0 : -1.0);
        const double far = std::ldexp(double(1 + rnd.index(1024)), int(rnd.index(21))) * (rnd.chance(0.5) ? 1.0 : -1.0) *
                           (rnd.chance(0.25) ? 1.0 : 4096.0);
        if (std::abs(far) < 4.0 * std::abs(near)) continue;
        const double h = -0.5 * a * (near + far), c = a * near * far;
        const double half = 0.5 * a * (far - near), disc = half * half;
        const rc::QuadraticRoots got = rc::stableQuadraticRoots(a, h, c, disc);
        INFO(std::setprecision(17) << a << " t^2 + 2 (" << h << ") t + " << c << " = 0, disc " << disc
                                   << ": roots " << far << " and " << near << "; yours: larger " << got.larger
                                   << ", smaller " << got.smaller);
        // Each root to 1e-12 of itself (the truncated cones take their roots from here too)
        REQUIRE(std::abs(got.larger - far) <= 1e-12 * std::abs(far));
        REQUIRE(std::abs(got.smaller - near) <= 1e-12 * std::abs(near));
    }
}

TEST_CASE("far.nff drawn with your roots matches the oracle's", "[tutorial06]") {
    // Spheres of radius about 1 a billion units from the eye: each pixel's eye ray is
    // tested against every sphere with your roots, the nearest root in front wins
    const rc::Scene s = rc::readNffFile(TUTORIAL_DIR "/far.nff");
    const int w = 64, h = 64;
    const rc::RayGenerator camera(s.camera, w, h);
    auto firstHit = [&](const rc::Ray& ray, auto roots) {
        // The least (distance, sphere) pair: ties go to the lower index, as in the renderer
        std::pair<double, int> least{rc::kNoHit, -1};
        for (int j = 0; j < int(s.spheres.size()); ++j) {
            const auto r = roots(ray, s.spheres[j]);
            least = std::min(least, {!r.hit ? rc::kNoHit : r.t0 > 0.0 ? r.t0 : r.t1 > 0.0 ? r.t1 : rc::kNoHit, j});
        }
        return least.first < rc::kNoHit ? rc::Answer{least.second, least.first} : rc::Answer{};
    };
    tutorial::Picture pic(w, h);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const rc::Ray ray = camera.primary(x, y);
            const rc::Answer mine = firstHit(ray, rc::sphereRootsStable);
            const rc::Answer want{tutorial::oracleFirstHit(ray, s.spheres), 0.0};
            tutorial::Rgb c = tutorial::labelColour(mine.object);
            if (mine.object >= 0) {
                // Shade by the normal at your hit point, facing the light
                const rc::Vec3 n = glm::normalize(ray.at(mine.t) - s.spheres[mine.object].c);
                const rc::Vec3 l = glm::normalize(s.lights.at(0).position - s.spheres[mine.object].c);
                c = tutorial::shade(c, 0.25 + 0.75 * std::max(0.0, glm::dot(n, l)));
            }
            wrong += mine.object != want.object;
            pic.set(x, y, c);
        }
    const std::string path = pic.save("far", 6);
    tutorial::announcePicture("far.nff with your roots: " + std::to_string(wrong) + " pixel(s) hit differently", path);
    INFO(std::setprecision(17) << wrong << " pixel(s) of far.nff hit a different sphere (or none) with your roots: see " << path);
    REQUIRE(wrong == 0);
}
