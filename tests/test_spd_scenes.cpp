// The whole NFF format as SPD writes it: every scene in scenes/ reads and renders, cones
// and concave polygons intersect exactly, closed meshes are watertight, and every cache,
// order and search gives the same image on every scene.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/intersection.h"
#include "geometry/polygon.h"
#include "geometry/truncated_cone.h"
#include "render/render_session.h"
#include "scene/nff_reader.h"
#include "uniform.h"

using namespace rc;

namespace {

const std::string kScenes = RAYCACHE_SCENES_DIR;

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// How many tokens of the file are `keyword`: the reader reads tokens, and SPD puts
/// several primitives on one line.
int countKeyword(const std::string& text, const std::string& keyword) {
    std::istringstream in(text);
    std::string token;
    int n = 0;
    while (in >> token) n += token == keyword;
    return n;
}

Ray rayThrough(const Vec3& from, const Vec3& to) { return {from, glm::normalize(to - from)}; }

}  // namespace

TEST_CASE("every scene in scenes/ reads with the primitives its file holds", "[nff][spd]") {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".nff") continue;
        ++files;
        const std::string text = slurp(entry.path().string());
        INFO(entry.path());
        const Scene s = readNffFile(entry.path().string());
        // A cone keyword `c` is never a number, so counting tokens counts cones
        CHECK(int(s.spheres.size()) == countKeyword(text, "s"));
        CHECK(int(s.cones.size()) == countKeyword(text, "c"));
        CHECK(int(s.polygons.size()) == countKeyword(text, "p") + countKeyword(text, "pp"));
        CHECK(int(s.lights.size()) == countKeyword(text, "l"));
        CHECK(s.size() == int(s.spheres.size() + s.cones.size() + s.polygons.size()));
    }
    CHECK(files == 11);
}

TEST_CASE("SPD's ior 0 is read only where T > 0", "[nff]") {
    const std::string view = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 0.01 resolution 8 8\n";
    const Scene opaque = parseNff(view + "f 1 1 1 0.5 0.5 10 0 0\ns 0 0 0 1\n", "opaque");
    CHECK(opaque.materials[0].ior == 1.0);
    const Scene glass = parseNff(view + "f 1 1 1 0.1 0.1 10 0.9 1.5\ns 0 0 0 1\n", "glass");
    CHECK(glass.materials[0].ior == 1.5);
    CHECK_THROWS_AS(parseNff(view + "f 1 1 1 0.1 0.1 10 0.9 0\ns 0 0 0 1\n", "bad"), SceneError);
}

TEST_CASE("gears2 holds concave polygons with many vertices", "[nff][spd]") {
    const Scene s = readNffFile(kScenes + "/gears2.nff");
    std::size_t most = 0, concave = 0;
    for (const Polygon& p : s.polygons) {
        most = std::max(most, p.vertices.size());
        concave += !p.convex;
    }
    CHECK(most == 144);
    CHECK(concave > 0);
}

TEST_CASE("a cylinder: hits at hand-computed distances, open ends, rays from its surface", "[cone]") {
    TruncatedCone c;
    REQUIRE_FALSE(makeTruncatedCone({0, 0, 0}, 1.0, {0, 0, 4}, 1.0, c));
    // From outside, across the axis: the near wall at 5 - 1
    CHECK(intersectTruncatedCone(rayThrough({5, 0, 2}, {0, 0, 2}), c, false) == Approx(4.0));
    // Along the axis through the open ends: nothing
    CHECK(intersectTruncatedCone(rayThrough({0, 0, -3}, {0, 0, 2}), c, false) == kNoHit);
    // Beyond a rim: nothing
    CHECK(intersectTruncatedCone(rayThrough({5, 0, 4.5}, {0, 0, 4.5}), c, false) == kNoHit);
    // Inside, from its own wall, across: the opposite wall at 2 (the root at the origin is skipped)
    CHECK(intersectTruncatedCone(rayThrough({1, 0, 2}, {0, 0, 2}), c, true) == Approx(2.0));
    // Off its own wall, outward: it never comes back
    CHECK(intersectTruncatedCone(rayThrough({1, 0, 2}, {2, 0, 2}), c, true) == kNoHit);
    // A ray that enters through the open end sees the inside wall
    const double t = intersectTruncatedCone(rayThrough({0, 0, -1}, {0.5, 0, 1}), c, false);
    CHECK(t == Approx(2.0 * std::sqrt(0.25 + 4.0)));  // reaches x = 1 at z = 3
    // The outward normal points away from the axis
    CHECK(glm::dot(truncatedConeNormal(c, {0, 1, 1}), Vec3(0, 1, 0)) == Approx(1.0));
}

TEST_CASE("a cone: the slanted wall, grazing rays, and rays from the surface", "[cone]") {
    TruncatedCone c;
    REQUIRE_FALSE(makeTruncatedCone({0, 0, 0}, 2.0, {0, 0, 2}, 0.0, c));  // radius 2 - z
    // Across at height 1 (radius 1): hit at 5 - 1
    CHECK(intersectTruncatedCone(rayThrough({5, 0, 1}, {0, 0, 1}), c, false) == Approx(4.0));
    // The normal leans up by 45 degrees
    const Vec3 n = truncatedConeNormal(c, {1, 0, 1});
    CHECK(n.x == Approx(std::sqrt(0.5)));
    CHECK(n.z == Approx(std::sqrt(0.5)));
    // A ray along a generator line, just outside it, never hits
    const Vec3 dir = glm::normalize(Vec3(-1, 0, 1));
    CHECK(intersectTruncatedCone({Vec3(2.0 + 1e-9, 0, -0.0) - 0.5 * dir, dir}, c, false) == kNoHit);
    // From its own surface, going through the inside, it meets the far wall
    const Vec3 p{1, 0, 1};
    const double t = intersectTruncatedCone(rayThrough(p, {-1, 0, 1}), c, true);
    CHECK(t == Approx(2.0).epsilon(1e-12));  // the far wall at (-1, 0, 1)
}

TEST_CASE("grazing rays on a cylinder: the stable discriminant agrees with long double", "[cone]") {
    TruncatedCone c;
    REQUIRE_FALSE(makeTruncatedCone({0, 0, -1}, 1.0, {0, 0, 1}, 1.0, c));
    // Rays passing at distance 1 - eps from the axis, from far away
    for (double eps : {1e-3, 1e-6, 1e-9}) {
        const Ray r{{-1e4, 1.0 - eps, 0.0}, {1.0, 0.0, 0.0}};
        const double t = intersectTruncatedCone(r, c, false);
        const long double y = 1.0L - (long double)eps;
        const long double exact = 1e4L - std::sqrt(1.0L - y * y);
        INFO(eps);
        CHECK(double((t - exact) / exact) == Approx(0.0).margin(1e-12));
    }
}

TEST_CASE("concave polygons: the notch is empty, the body is hit", "[polygon]") {
    // An L shape in the z = 0 plane
    Polygon l;
    REQUIRE_FALSE(makePolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, {}, l));
    CHECK_FALSE(l.convex);
    CHECK(intersectPolygon(rayThrough({0.5, 1.5, 3}, {0.5, 1.5, 0}), l, false) == Approx(3.0));
    CHECK(intersectPolygon(rayThrough({1.5, 0.5, 3}, {1.5, 0.5, 0}), l, false) == Approx(3.0));
    CHECK(intersectPolygon(rayThrough({1.5, 1.5, 3}, {1.5, 1.5, 0}), l, false) == kNoHit);
    // An outline that folds across its own edge
    Polygon bow;
    const auto why = makePolygon({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, -1, 0}, {0, 4, 0}}, {}, bow);
    REQUIRE(why.has_value());
    CHECK(why->find("crosses itself") != std::string::npos);
}

TEST_CASE("closed meshes are watertight: a ray through a shared edge or vertex hits one face", "[polygon]") {
    // A cube of six quads and an octahedron of eight triangles, turned at random, with
    // coordinates that do not round nicely
    Random rng(1986);
    const Uniform u{-1.0, 1.0};
    const Vec3 cubeV[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int cubeF[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (int trial = 0; trial < 40; ++trial) {
        const glm::dmat4 m = glm::rotate(glm::dmat4(1.0), 3.0 * u(rng), glm::normalize(Vec3(u(rng), u(rng), u(rng) + 2.0)));
        const Vec3 centre{0.1 * u(rng), 0.3 * u(rng), 0.7 * u(rng)};
        const double scale = 1.37 + 0.1 * u(rng);
        Vec3 v[8];
        for (int i = 0; i < 8; ++i) v[i] = centre + scale * Vec3(m * glm::dvec4(cubeV[i], 1.0));
        std::vector<Polygon> faces(6);
        for (int f = 0; f < 6; ++f)
            REQUIRE_FALSE(makePolygon({v[cubeF[f][0]], v[cubeF[f][1]], v[cubeF[f][2]], v[cubeF[f][3]]}, {}, faces[f]));
        // Points on edges (at a random fraction) and at vertices, approached from outside
        // along the line towards the centre
        auto check = [&](const Vec3& target) {
            const Vec3 out = target + (2.0 + u(rng)) * (target - centre) + 0.2 * Vec3(u(rng), u(rng), u(rng));
            const Ray ray = rayThrough(out, target);
            int hits = 0;
            double first = kNoHit;
            for (const Polygon& f : faces) {
                const double t = intersectPolygon(ray, f, false);
                if (t == kNoHit) continue;
                ++hits;
                first = std::min(first, t);
            }
            // In and out: exactly two faces, one where it enters, one where it leaves
            CHECK(hits == 2);
            CHECK(first == Approx(glm::length(target - out)).epsilon(1e-9));
        };
        for (int f = 0; f < 6; ++f)
            for (int e = 0; e < 4; ++e) {
                const Vec3 a = v[cubeF[f][e]], b = v[cubeF[f][(e + 1) % 4]];
                const double s = 0.5 + 0.49 * u(rng);
                check(a + s * (b - a));
            }
        for (int i = 0; i < 8; ++i) check(v[i]);
    }
}

TEST_CASE("every scene in scenes/: every cache, order and search gives the same image", "[spd][exact]") {
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".nff") continue;
        auto scene = std::make_shared<const Scene>(readNffFile(entry.path().string()));
        RenderOptions base;
        base.width = 24;
        base.height = 24;
        base.band = 6;
        RenderSession reference(scene, base);
        reference.run();
        const auto expected = reference.image().rgb8();
        for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh})
            for (CacheKind cache : allCacheKinds())
                for (OrderKind order : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst}) {
                    RenderOptions opt = base;
                    opt.accel = accel;
                    opt.cache = cache;
                    opt.order = order;
                    opt.verify = true;
                    RenderSession r(scene, opt);
                    r.run();
                    INFO(entry.path().stem().string() << " " << toString(accel) << " " << toString(cache) << " "
                                                      << toString(order));
                    REQUIRE(r.counters().verifyDisagreements == 0);
                    REQUIRE(r.image().rgb8() == expected);
                    REQUIRE(r.counters().totalRays() == reference.counters().totalRays());
                }
    }
}

TEST_CASE("gears2's transmitters reflect: one reflection ray beside every refraction ray", "[spd][shading]") {
    // SPD's gears write their transmitters with Ks 0; SPD's rules 8 and 9 count a
    // reflection ray at every transmitter hit. The ground (Ks 0.6) reflects too, and the
    // opaque gears (Ks 0) do not, so reflections outnumber refractions
    const auto scene = std::make_shared<const Scene>(readNffFile(kScenes + "/gears2.nff"));
    RenderOptions opt;
    opt.width = 64;
    opt.height = 64;
    opt.accel = AccelKind::Bvh;
    RenderSession r(scene, opt);
    r.run();
    const Counters& n = r.counters();
    REQUIRE(n.rays[int(RayKind::Refraction)] > 0);
    CHECK(n.rays[int(RayKind::Reflection)] > n.rays[int(RayKind::Refraction)]);
}
