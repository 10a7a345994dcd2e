// The built-in balls:N against SPD's own output (scenes/balls1.nff, balls2.nff), its shape
// at larger sizes, its limits, and its image against the file's.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>

#include <glm/geometric.hpp>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"
#include "scene/sphereflake.h"

using namespace rc;

namespace {

const std::string kScenes = RAYCACHE_SCENES_DIR;

/// Requires `made` to be the scene the NFF reader made of `read`, number for number.
void requireSameScene(const Scene& made, const Scene& read) {
    REQUIRE(made.background == read.background);
    const Camera &a = made.camera, &b = read.camera;
    REQUIRE(a.from == b.from);
    REQUIRE(a.at == b.at);
    REQUIRE(a.up == b.up);
    REQUIRE(a.angle == b.angle);
    REQUIRE(a.hither == b.hither);
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);

    REQUIRE(made.lights.size() == read.lights.size());
    for (std::size_t i = 0; i < made.lights.size(); ++i) {
        REQUIRE(made.lights[i].position == read.lights[i].position);
        REQUIRE(made.lights[i].color == read.lights[i].color);
        REQUIRE(made.lights[i].radius == read.lights[i].radius);
    }

    REQUIRE(made.materials.size() == read.materials.size());
    for (std::size_t i = 0; i < made.materials.size(); ++i) {
        const Material &m = made.materials[i], &n = read.materials[i];
        INFO("material " << i);
        REQUIRE(m.color == n.color);
        REQUIRE(m.kd == n.kd);
        REQUIRE(m.ks == n.ks);
        REQUIRE(m.shine == n.shine);
        REQUIRE(m.kt == n.kt);
        REQUIRE(m.ior == n.ior);
    }

    REQUIRE(made.polygons.size() == read.polygons.size());
    for (std::size_t i = 0; i < made.polygons.size(); ++i) {
        REQUIRE(made.polygons[i].vertices == read.polygons[i].vertices);
        REQUIRE(made.polygons[i].vertexNormals.empty());
    }

    // Every sphere in SPD's order: within the printed precision, and in fact the very
    // doubles the reader makes of SPD's %g
    REQUIRE(made.spheres.size() == read.spheres.size());
    for (std::size_t i = 0; i < made.spheres.size(); ++i) {
        const Sphere &s = made.spheres[i], &t = read.spheres[i];
        INFO("sphere " << i << ": " << s.c.x << " " << s.c.y << " " << s.c.z << " " << s.r << " vs " << t.c.x
                       << " " << t.c.y << " " << t.c.z << " " << t.r);
        REQUIRE(glm::length(s.c - t.c) <= 1e-4);
        REQUIRE(std::abs(s.r - t.r) <= 1e-4);
        REQUIRE(s.c == t.c);
        REQUIRE(s.r == t.r);
    }

    REQUIRE(made.objects.size() == read.objects.size());
    for (std::size_t i = 0; i < made.objects.size(); ++i) {
        REQUIRE(made.objects[i].shape == read.objects[i].shape);
        REQUIRE(made.objects[i].index == read.objects[i].index);
        REQUIRE(made.objects[i].material == read.objects[i].material);
    }
    REQUIRE(made.bound.c == read.bound.c);
    REQUIRE(made.bound.r == read.bound.r);
}

/// The rejection message for `spec`, or "" when it builds.
std::string rejection(const std::string& spec) {
    try {
        makeBuiltin(spec);
    } catch (const SceneError& e) {
        CHECK(e.file == spec);
        return e.message;
    }
    return {};
}

}  // namespace

TEST_CASE("balls:1 and balls:2 are SPD's balls -s 1 and -s 2, number for number", "[sphereflake]") {
    for (int n : {1, 2}) {
        INFO("balls:" << n);
        const Scene made = makeBuiltin("balls:" + std::to_string(n));
        const Scene read = readNffFile(kScenes + "/balls" + std::to_string(n) + ".nff");
        CHECK(made.name == "balls:" + std::to_string(n));
        REQUIRE(long(made.spheres.size()) == sphereflakeSpheres(n));
        requireSameScene(made, read);
    }
}

TEST_CASE("balls:N has 1 + 9 + ... + 9^N spheres, each touching its parent at a third of its radius",
          "[sphereflake]") {
    CHECK(sphereflakeSpheres(1) == 10);
    CHECK(sphereflakeSpheres(2) == 91);
    CHECK(sphereflakeSpheres(4) == 7381);
    CHECK(sphereflakeSpheres(6) == 597871);
    for (int n = 1; n <= 4; ++n) {
        INFO("balls:" << n);
        const Scene s = makeSphereflake(n);
        REQUIRE(long(s.spheres.size()) == sphereflakeSpheres(n));
        REQUIRE(s.polygons.size() == 1);
        REQUIRE(s.lights.size() == 3);
    }
    // Depth first: a sphere at level l is followed by its 9 subtrees of sphereflakeSpheres(3 - l - 1)
    // spheres each. Every child touches its parent from outside, with a third of its radius
    const Scene s = makeSphereflake(3);
    int checked = 0;
    const auto walk = [&](auto&& self, std::size_t at, int levelsBelow) -> std::size_t {
        const Sphere parent = s.spheres[at];
        std::size_t next = at + 1;
        if (levelsBelow == 0) return next;
        for (int k = 0; k < 9; ++k) {
            const Sphere& child = s.spheres[next];
            INFO("sphere " << next << " child of " << at);
            // SPD prints six significant digits: coordinates up to 0.5e-6 off
            REQUIRE(child.r == Approx(parent.r / 3.0).epsilon(1e-5));
            REQUIRE(glm::length(child.c - parent.c) == Approx(parent.r + child.r).margin(2e-6));
            ++checked;
            next = self(self, next, levelsBelow - 1);
        }
        return next;
    };
    REQUIRE(walk(walk, 0, 3) == s.spheres.size());
    REQUIRE(checked == 819);
    // Nothing sinks through the ground square (z = -0.5, level with the big sphere's bottom)
    for (const Sphere& sp : s.spheres) REQUIRE(sp.c.z - sp.r >= -0.5 - 1e-6);
}

TEST_CASE("balls:N rejects sizes out of range, before any work", "[sphereflake]") {
    const std::string usage = "balls:N with N a whole number from 1 to " + std::to_string(kMaxSphereflake);
    for (const char* bad : {"balls", "balls:", "balls:0", "balls:7", "balls:-1", "balls:x", "balls:4x", "balls: 4",
                            "balls:99999999999999999999"}) {
        INFO(bad);
        CHECK(rejection(bad).find(usage) != std::string::npos);
    }
    CHECK_THROWS_AS(makeSphereflake(0), SceneError);
    CHECK_THROWS_AS(makeSphereflake(kMaxSphereflake + 1), SceneError);
    CHECK(rejection("balls:3").empty());
}

TEST_CASE("balls:2 renders to the same bytes as scenes/balls2.nff", "[sphereflake][exact]") {
    const auto made = std::make_shared<const Scene>(makeBuiltin("balls:2"));
    const auto read = std::make_shared<const Scene>(readNffFile(kScenes + "/balls2.nff"));
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Bvh}) {
        RenderOptions opt;
        opt.width = 40;
        opt.height = 40;
        opt.accel = accel;
        opt.cache = CacheKind::Blocker;
        opt.order = OrderKind::BreadthFirst;
        RenderSession a(made, opt), b(read, opt);
        a.run();
        b.run();
        INFO(toString(accel));
        REQUIRE(a.counters().totalRays() == b.counters().totalRays());
        REQUIRE(a.counters().totalRays() > 40 * 40);
        REQUIRE(a.image().rgb8() == b.image().rgb8());
    }
}

TEST_CASE("balls:4 makes the rays SPD published for it, within SPD's 10%", "[sphereflake][spd]") {
    // SPD's README, for the default-size balls at 512x512, depth 5 (the eye ray is depth 1),
    // no adaptive cutoff: 175,095 reflection rays, 954,368 shadow rays, no refraction. SPD
    // shoots 513x513 eye rays through pixel corners, RayCache 512x512: 0.4% fewer
    RenderOptions opt;
    opt.width = 512;
    opt.height = 512;
    opt.accel = AccelKind::Bvh;
    RenderSession r(std::make_shared<const Scene>(makeBuiltin("balls:4")), opt);
    r.run();
    const Counters& n = r.counters();
    CHECK(double(n.rays[int(RayKind::Reflection)]) == Approx(175095.0).epsilon(0.10));
    CHECK(double(n.rays[int(RayKind::Shadow)]) == Approx(954368.0).epsilon(0.10));
    CHECK(n.rays[int(RayKind::Refraction)] == 0);
}
