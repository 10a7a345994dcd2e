// Tests of the built-in scene generators and loadScene().
#include <catch2/catch.hpp>

#include <random>

#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "scene/builtin_scenes.h"
#include "search/standard_algorithm.h"

using namespace rc;

namespace {


bool sameScene(const Scene& a, const Scene& b) {
    if (a.spheres.size() != b.spheres.size() || a.objects.size() != b.objects.size() ||
        a.lights.size() != b.lights.size() || a.materials.size() != b.materials.size())
        return false;
    for (std::size_t i = 0; i < a.spheres.size(); ++i)
        if (a.spheres[i].c != b.spheres[i].c || a.spheres[i].r != b.spheres[i].r) return false;
    for (std::size_t i = 0; i < a.objects.size(); ++i)
        if (a.objects[i].material != b.objects[i].material) return false;
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        if (a.lights[i].position != b.lights[i].position) return false;
    return a.camera.from == b.camera.from && a.camera.at == b.camera.at;
}

std::string errorMessage(const std::string& spec) {
    try {
        makeBuiltin(spec);
    } catch (const SceneError& e) {
        CHECK(e.file == spec);
        CHECK(e.line == 0);
        CHECK(e.column == 0);
        CHECK(std::string(e.what()).rfind(spec + ":0:0: ", 0) == 0);
        return e.message;
    }
    FAIL("no SceneError for " << spec);
    return {};
}

/// The object `ray` (an eye ray) hits first, or -1: the library's complete search. (The
/// scenes tested with it hold only spheres, object k being sphere k.)
int nearestSphere(const Scene& s, const Ray& ray, double& tHit) {
    Query q;
    q.ray = ray;
    Counters n;
    const Answer a = standardAlgorithm(s, q, n);
    tHit = a.t;
    return a.object;
}

}  // namespace

TEST_CASE("builtinScenes lists every generator with a description", "[builtin]") {
    const auto list = builtinScenes();
    REQUIRE(list.size() == 6);
    CHECK(list[0].name == "cube:N");
    CHECK(list[1].name == "balls:N");
    for (const BuiltinInfo& b : list) {
        CHECK_FALSE(b.description.empty());
        // A sized scene suggests sizes, and every one of them builds
        const bool sized = b.name.size() > 2 && b.name.substr(b.name.size() - 2) == ":N";
        CHECK(sized == !b.sizes.empty());
        for (int n : b.sizes)
            CHECK_NOTHROW(makeBuiltin(b.name.substr(0, b.name.size() - 1) + std::to_string(n)));
        const std::string spec = sized ? b.name.substr(0, b.name.size() - 1) + "2" : b.name;
        const Scene s = makeBuiltin(spec);
        CHECK(s.name == spec);
        CHECK(s.size() > 0);
        CHECK(s.lights.size() >= 1);
        CHECK(s.bound.r > 0.0);
    }
}

TEST_CASE("cube:N has N^3 spheres with the paper's jitter", "[builtin]") {
    for (int n : {1, 2, 3, 5, 8}) {
        const Scene s = makeBuiltin("cube:" + std::to_string(n));
        INFO(n);
        CHECK(int(s.spheres.size()) == n * n * n);
        CHECK(s.polygons.empty());
        CHECK(s.lights.size() == 2);
        CHECK(s.camera.width == 512);
        CHECK(s.camera.height == 512);
        CHECK(s.camera.angle == 40.0);
        CHECK(s.camera.hither == 1e-3);
        CHECK_FALSE(s.hasTransparency());
        const double half = 0.5 * (n - 1);
        for (const Sphere& sp : s.spheres) {
            CHECK(sp.r >= 0.25);
            CHECK(sp.r <= 0.45);
            for (int k = 0; k < 3; ++k) {
                const double cell = std::round(sp.c[k] + half);
                CHECK(std::abs(sp.c[k] + half - cell) <= 0.15);
            }
        }
        for (const Material& m : s.materials) {
            CHECK(m.kd == 0.6);
            CHECK(m.ks == 0.4);
            CHECK(m.shine == 30.0);
            CHECK(m.kt == 0.0);
        }
    }
}

TEST_CASE("cube:N fills the view: every sphere inside it, the bound just fitting", "[builtin]") {
    const Scene s = makeBuiltin("cube:6");
    const Camera& c = s.camera;
    const Vec3 forward = glm::normalize(c.at - c.from);
    const double halfAngle = 0.5 * c.angle * std::numbers::pi / 180.0;
    // The camera looks at the bound's centre, and the bound's silhouette is the view's edge
    CHECK(glm::length(glm::cross(forward, s.bound.c - c.from)) == Approx(0.0).margin(1e-9));
    CHECK(glm::length(c.from - s.bound.c) * std::sin(halfAngle) == Approx(s.bound.r));
    // ... so every sphere is in view, as it lies inside the bound
    for (const Sphere& sp : s.spheres) CHECK(glm::length(sp.c - s.bound.c) + sp.r <= s.bound.r);
    // The centre pixel looks into the cube; lights lie outside every sphere
    RayGenerator gen(c, c.width, c.height);
    double t = 0.0;
    CHECK(nearestSphere(s, gen.primary(0.5 * (c.width - 1), 0.5 * (c.height - 1)), t) >= 0);
    for (const Light& l : s.lights)
        for (const Sphere& sp : s.spheres) CHECK(glm::length(l.position - sp.c) > sp.r);
}

TEST_CASE("built-in scenes are deterministic for a seed and vary with it", "[builtin]") {
    CHECK(sameScene(makeBuiltin("cube:4", 7), makeBuiltin("cube:4", 7)));
    CHECK(sameScene(makeBuiltin("cube:4"), makeBuiltin("cube:4", 1986)));
    CHECK_FALSE(sameScene(makeBuiltin("cube:4", 7), makeBuiltin("cube:4", 8)));
    CHECK(sameScene(makeBuiltin("glass", 3), makeBuiltin("glass", 3)));
    CHECK_FALSE(sameScene(makeBuiltin("glass", 3), makeBuiltin("glass", 4)));
    // fill and pair are fixed scenes
    CHECK(sameScene(makeBuiltin("fill", 1), makeBuiltin("fill", 2)));
    CHECK(sameScene(makeBuiltin("pair", 1), makeBuiltin("pair", 2)));
    CHECK(sameScene(makeBuiltin("trio", 1), makeBuiltin("trio", 2)));
}

TEST_CASE("trio puts its third sphere between the other two, touching neither", "[builtin]") {
    // That it lies inside their hull is the instructor's test (tests/instructor/test_hull_oracles.cpp:
    // it measures the hull apart from the library, tutorial 03's answer)
    const Scene s = makeBuiltin("trio");
    REQUIRE(s.spheres.size() == 3);
    const Sphere &a = s.spheres[0], &b = s.spheres[1], &c = s.spheres[2];
    CHECK(glm::length(c.c - a.c) > a.r + c.r);
    CHECK(glm::length(c.c - b.c) > b.r + c.r);
    // Off the axis between them, so most rays from one to the other pass it
    const Vec3 axis = glm::normalize(b.c - a.c);
    const Vec3 off = (c.c - a.c) - axis * glm::dot(c.c - a.c, axis);
    CHECK(glm::length(off) > c.r);
}

TEST_CASE("cube:N is the same on every machine", "[builtin]") {
    // The generator is the standard's: its 10000th output from the default seed is fixed
    // by the C++ standard ([rand.predef])
    std::mt19937_64 standard;
    standard.discard(9999);
    REQUIRE(standard() == 9981545732273789042ull);
    // cube:1's sphere is the first four outputs for seed 1986, each 53 bits scaled to
    // [0, 1): jitter +-0.15 around the origin, radius in [0.25, 0.45]
    std::mt19937_64 gen(1986);
    auto unit = [&] { return double(gen() >> 11) / 9007199254740992.0; };
    const double x = -0.15 + 0.3 * unit(), y = -0.15 + 0.3 * unit(), z = -0.15 + 0.3 * unit();
    const double r = 0.25 + 0.2 * unit();
    const Scene s = makeBuiltin("cube:1", 1986);
    REQUIRE(s.spheres.size() == 1);
    CHECK(s.spheres[0].c.x == Approx(x).epsilon(1e-15));
    CHECK(s.spheres[0].c.y == Approx(y).epsilon(1e-15));
    CHECK(s.spheres[0].c.z == Approx(z).epsilon(1e-15));
    CHECK(s.spheres[0].r == Approx(r).epsilon(1e-15));
}

TEST_CASE("unknown names and bad sizes throw with a clear message", "[builtin]") {
    CHECK(errorMessage("nope").find("unknown scene 'nope'") != std::string::npos);
    CHECK(errorMessage("nope").find("cube:N, balls:N, glass, fill, pair") != std::string::npos);
    CHECK(errorMessage("").find("unknown scene") != std::string::npos);
    for (const char* bad : {"cube", "cube:", "cube:0", "cube:65", "cube:-1", "cube:abc", "cube:4x",
                            "cube: 4", "cube:99999999999999999999"}) {
        INFO(bad);
        CHECK(errorMessage(bad).find("cube:N with N a whole number from 1 to 64") != std::string::npos);
    }
    CHECK(makeBuiltin("cube:64", 1).spheres.size() == 64u * 64u * 64u);
}

TEST_CASE("glass: refracting spheres among opaque ones on a ground square", "[builtin]") {
    const Scene s = makeBuiltin("glass");
    CHECK(s.camera.width == 512);
    CHECK(s.lights.size() == 2);
    REQUIRE(s.polygons.size() == 1);
    CHECK(s.polygons[0].normal.y == Approx(1.0));
    CHECK(s.hasTransparency());
    int glass = 0, opaque = 0;
    for (const Object& o : s.objects) {
        if (o.shape != Shape::Sphere) continue;
        const Material& m = s.materials[o.material];
        if (m.kt > 0.0) {
            CHECK(m.kt >= 0.8);
            CHECK(m.kt <= 0.9);
            CHECK(m.ior == 1.5);
            ++glass;
        } else {
            ++opaque;
        }
    }
    CHECK(glass >= 3);
    CHECK(opaque >= 3);
    // Standing on the ground, not overlapping one another
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        CHECK(s.spheres[i].c.y == Approx(s.spheres[i].r));
        for (std::size_t j = i + 1; j < s.spheres.size(); ++j)
            CHECK(glm::length(s.spheres[i].c - s.spheres[j].c) > s.spheres[i].r + s.spheres[j].r);
    }
}

TEST_CASE("fill: every eye ray hits the sphere at a lit point", "[builtin]") {
    const Scene s = makeBuiltin("fill");
    REQUIRE(s.spheres.size() == 1);
    REQUIRE(s.lights.size() == 1);
    CHECK(s.size() == 1);
    const Camera& c = s.camera;
    CHECK(c.width == 64);
    CHECK(c.height == 64);
    const Material& m = s.materials[s.objects[0].material];
    CHECK(m.ks == 0.0);
    CHECK(m.kt == 0.0);
    RayGenerator gen(c, c.width, c.height);
    const double w = c.width - 1, h = c.height - 1;
    for (auto [x, y] : {std::pair{0.0, 0.0}, {w, 0.0}, {0.0, h}, {w, h}}) {
        INFO(x << ", " << y);
        CHECK(intersectSphere(gen.primary(x, y), s.spheres[0], Start::Elsewhere) < kNoHit);
    }
    // Every pixel, not only the corners, and every hit point faces the light
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            const Ray r = gen.primary(x, y);
            const double t = intersectSphere(r, s.spheres[0], Start::Elsewhere);
            REQUIRE(t < kNoHit);
            const Vec3 p = r.at(t);
            CHECK(glm::dot(s.lights[0].position - p, s.normal(0, p)) > 0.0);
        }
}

TEST_CASE("pair: a reflected ray from the big sphere hits the small one", "[builtin]") {
    const Scene s = makeBuiltin("pair");
    REQUIRE(s.spheres.size() == 2);
    CHECK(s.lights.size() == 1);
    CHECK(s.camera.width == 256);
    const int big = s.spheres[0].r > s.spheres[1].r ? 0 : 1;
    const int small = 1 - big;
    CHECK(s.materials[s.objects[big].material].ks >= 0.5);
    const Camera& c = s.camera;
    RayGenerator gen(c, c.width, c.height);
    int reflectedHits = 0, smallSeen = 0;
    for (int y = 0; y < c.height; y += 2)
        for (int x = 0; x < c.width; x += 2) {
            const Ray r = gen.primary(x, y);
            double t = 0.0;
            const int hit = nearestSphere(s, r, t);
            if (hit == small) ++smallSeen;
            if (hit != big) continue;
            const Vec3 p = r.at(t);
            const Vec3 n = s.normal(big, p);
            const Ray refl{p, glm::normalize(r.d - 2.0 * glm::dot(r.d, n) * n)};
            if (intersectSphere(refl, s.spheres[small], Start::Elsewhere) < kNoHit) ++reflectedHits;
        }
    CHECK(reflectedHits > 10);
    CHECK(smallSeen > 10);
}

TEST_CASE("loadScene reads files and .nff names, and builds everything else", "[builtin]") {
    const Scene balls = loadScene(std::string(RAYCACHE_SCENES_DIR) + "/balls1.nff");
    CHECK(balls.name == "balls1");
    CHECK(balls.polygons.size() == 1);
    CHECK(loadScene("fill").name == "fill");
    CHECK(loadScene("cube:3", 5).spheres.size() == 27);
    CHECK(sameScene(loadScene("cube:3", 5), makeBuiltin("cube:3", 5)));
    try {
        loadScene("no-such-scene.nff");
        FAIL("no error");
    } catch (const SceneError& e) {
        CHECK(e.line == 0);
        CHECK(e.message.find("cannot open") != std::string::npos);
    }
    CHECK_THROWS_AS(loadScene("no-such-scene"), SceneError);
}
