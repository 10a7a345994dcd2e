// Whitted shading against values computed by hand: Snell's law, the critical angle and
// total internal reflection, the Phong highlight, the 1/sqrt(n) light scale, the normals
// of `pp` patches; and the camera's projection, the inverse of its eye rays.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/camera.h"
#include "scene/scene.h"
#include "trace/fresnel.h"
#include "trace/shading.h"
#include "uniform.h"

using namespace rc;

namespace {
/// A unit sphere at the origin with material `m` and `lights` lights at `light`.
Scene unitSphere(const Material& m, int lights = 1, Vec3 light = Vec3(0.0, 0.0, 10.0)) {
    Scene s;
    s.addMaterial(m);
    s.addSphere({Vec3(0.0), 1.0}, 0);
    for (int k = 0; k < lights; ++k) s.lights.push_back({light, Vec3(1.0)});
    s.finalize();
    return s;
}

/// Shades one ray of `s` that hits object 0 at distance `t`; returns its children.
std::vector<RayTask> shadeHit(const Scene& s, const Ray& ray, double t, RayOrigin from = {}, int depth = 1) {
    RayTask task = primaryTask(ray, 0);
    task.query.origin = from;
    task.depth = depth;
    ImageAccumulator image(1, 1);
    std::vector<RayTask> children;
    shade(s, task, Answer{0, t}, ShadingOptions{}, image, children);
    return children;
}

const RayTask& child(const std::vector<RayTask>& c, RayKind kind) {
    for (const RayTask& t : c)
        if (t.query.kind == kind) return t;
    FAIL("no child ray of this kind");
    return c.front();
}

const Material kGlass{Vec3(1.0), 0.5, 0.3, 10.0, 0.6, 1.5};
}  // namespace

TEST_CASE("refraction obeys Snell's law entering glass", "[shading][physics]") {
    const Scene s = unitSphere(kGlass);
    // Down the z axis at x = 0.5: it meets the sphere where sin(incidence) = 0.5
    const Ray ray{Vec3(0.5, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
    const double t = 5.0 - std::sqrt(0.75);
    const RayTask r = child(shadeHit(s, ray, t), RayKind::Refraction);
    const Vec3 n = glm::normalize(ray.at(t));
    // sin(refraction) = sin(incidence) / 1.5 = 1/3, bent towards the inward normal
    const Vec3 d = r.query.ray.d;
    REQUIRE(glm::length(glm::cross(d, -n)) == Approx(1.0 / 3.0).epsilon(1e-12));
    REQUIRE(glm::dot(d, -n) > 0.0);
    REQUIRE(d.x < 0.0);  // towards the axis: the ray was at x > 0 going down
    REQUIRE(d.y == 0.0);  // in the plane of incidence
    REQUIRE(r.query.origin == RayOrigin{0, true});
    // Kt times what the boundary lets through: cos i = sqrt(3)/2, cos t = sqrt(8)/3 by
    // Snell, and Fresnel reflects the mean square of r_s and r_p (0.0415)
    const double ci = std::sqrt(3.0) / 2.0, ct = std::sqrt(8.0) / 3.0;
    const double rs = (ci - 1.5 * ct) / (ci + 1.5 * ct), rp = (1.5 * ci - ct) / (1.5 * ci + ct);
    const double reflected = 0.5 * (rs * rs + rp * rp);
    REQUIRE(reflected == Approx(0.0415226).epsilon(1e-5));
    REQUIRE(r.weight.x == Approx(0.6 * (1.0 - reflected)).epsilon(1e-14));
    // reflection: the mirror direction, weighted by Ks, which is larger than Fresnel here
    const RayTask m = child(shadeHit(s, ray, t), RayKind::Reflection);
    REQUIRE(glm::length(m.query.ray.d - (ray.d - 2.0 * glm::dot(ray.d, n) * n)) < 1e-14);
    REQUIRE(m.weight == Vec3(0.3));
}

TEST_CASE("leaving glass: Snell below the critical angle, total internal reflection above", "[shading][physics]") {
    const Scene s = unitSphere(kGlass);
    const double critical = std::asin(1.0 / 1.5);  // 41.8 degrees
    SECTION("sin(incidence) = 0.6 < 2/3: out, with sin(refraction) = 0.9") {
        REQUIRE(std::asin(0.6) < critical);
        const Ray ray{Vec3(0.6, 0.0, -0.5), Vec3(0.0, 0.0, 1.0)};  // inside, hits (0.6, 0, 0.8)
        const RayTask r = child(shadeHit(s, ray, 1.3, {0, true}), RayKind::Refraction);
        const Vec3 n(0.6, 0.0, 0.8);
        REQUIRE(glm::length(glm::cross(r.query.ray.d, n)) == Approx(0.9).epsilon(1e-12));
        REQUIRE(glm::dot(r.query.ray.d, n) > 0.0);  // out of the sphere
        REQUIRE(r.query.origin == RayOrigin{0, false});
    }
    SECTION("sin(incidence) = 0.8 > 2/3: reflected back inside, all of it, and nothing refracted") {
        REQUIRE(std::asin(0.8) > critical);
        const Ray ray{Vec3(0.8, 0.0, -0.5), Vec3(0.0, 0.0, 1.0)};  // inside, hits (0.8, 0, 0.6)
        const std::vector<RayTask> c = shadeHit(s, ray, 1.1, {0, true});
        for (const RayTask& t : c) REQUIRE(t.query.kind != RayKind::Refraction);
        const RayTask& r = child(c, RayKind::Reflection);
        // d - 2 (d.n) n with n = (0.8, 0, 0.6), d.n = 0.6
        REQUIRE(glm::length(r.query.ray.d - Vec3(-0.96, 0.0, 0.28)) < 1e-12);
        REQUIRE(r.query.origin == RayOrigin{0, true});
        REQUIRE(r.weight == Vec3(1.0));  // Fresnel: the boundary reflects everything
    }
}

TEST_CASE("Fresnel's equations at the angles worked by hand", "[shading][physics]") {
    // Head-on: ((n2 - n1) / (n2 + n1))^2 either way
    CHECK(fresnelDielectric(1.0, 1.0, 1.5) == Approx(0.04).epsilon(1e-12));
    CHECK(fresnelDielectric(1.0, 1.5, 1.0) == Approx(0.04).epsilon(1e-12));
    CHECK(fresnelDielectric(1.0, 1.0, 1.1) == Approx(0.01 / 4.41).epsilon(1e-12));
    // Grazing: everything
    CHECK(fresnelDielectric(0.0, 1.0, 1.5) == Approx(1.0));
    // At Brewster's angle, tan i = n2 / n1, r_p vanishes: the fraction is r_s^2 / 2 with
    // r_s = (n1^2 - n2^2) / (n1^2 + n2^2) = -5/13 for 1 -> 1.5
    const double brewster = std::atan(1.5);
    CHECK(fresnelDielectric(std::cos(brewster), 1.0, 1.5) == Approx(0.5 * 25.0 / 169.0).epsilon(1e-12));
    // Reversing the path reflects as much (sin t and sin i swap)
    const double ci = std::cos(0.7), st = std::sin(0.7) / 1.5;
    CHECK(fresnelDielectric(std::sqrt(1.0 - st * st), 1.5, 1.0) == Approx(fresnelDielectric(ci, 1.0, 1.5)).epsilon(1e-12));
    // Beyond the critical angle from inside: total internal reflection
    CHECK(fresnelDielectric(0.6, 1.5, 1.0) == 1.0);  // sin i = 0.8 > 1 / 1.5
    CHECK(fresnelDielectric(0.8, 1.5, 1.0) < 1.0);   // sin i = 0.6 < 1 / 1.5
}

TEST_CASE("every transmitter reflects, whatever its Ks (SPD's rules 8 and 9)", "[shading][physics][spd]") {
    // SPD's gears' transmitters: Kd 0.2, Ks 0, T 0.8, ior 1.1
    const Material gear{Vec3(1.0), 0.2, 0.0, 0.0, 0.8, 1.1};
    SECTION("a sphere: Fresnel weighs the reflection") {
        const Scene s = unitSphere(gear);
        const Ray down{Vec3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
        const std::vector<RayTask> c = shadeHit(s, down, 4.0);
        const RayTask& r = child(c, RayKind::Reflection);
        const double head = (0.1 / 2.1) * (0.1 / 2.1);  // ((n - 1) / (n + 1))^2
        REQUIRE(r.weight.x == Approx(head).epsilon(1e-12));
        REQUIRE(glm::length(r.query.ray.d - Vec3(0.0, 0.0, 1.0)) < 1e-14);
        REQUIRE(child(c, RayKind::Refraction).weight.x == Approx(0.8 * (1.0 - head)).epsilon(1e-12));
    }
    SECTION("a polygon, hit from either side: a reflection beside the ray straight through") {
        Scene s;
        s.addMaterial(gear);
        Polygon square;
        REQUIRE_FALSE(makePolygon({Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}, {}, square));
        s.addPolygon(square, 0);
        s.lights.push_back({Vec3(0.0, 0.0, 10.0), Vec3(1.0)});
        s.finalize();
        for (double side : {1.0, -1.0}) {
            const Ray ray{Vec3(0.3, 0.0, 2.0 * side), glm::normalize(Vec3(0.3, 0.4, -side))};
            const std::vector<RayTask> c = shadeHit(s, ray, glm::length(Vec3(0.3, 0.4, -side)) * 2.0);
            const RayTask& r = child(c, RayKind::Reflection);
            REQUIRE(r.weight.x > 0.0);
            REQUIRE(r.query.ray.d.z * side > 0.0);  // back on the side it came from
            REQUIRE(child(c, RayKind::Refraction).query.ray.d == ray.d);
        }
    }
    SECTION("at depth 5, SPD's limit, nothing more") {
        const Scene s = unitSphere(gear);
        const Ray down{Vec3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
        for (const RayTask& t : shadeHit(s, down, 4.0, {}, 5)) REQUIRE(t.query.kind == RayKind::Shadow);
    }
}

TEST_CASE("the Phong highlight peaks in the mirror direction at Ks", "[shading][physics]") {
    const Material m{Vec3(1.0), 0.5, 0.3, 10.0, 0.0, 1.0};
    // The top of the sphere (0, 0, 1), the light up and to +x at 45 degrees
    const Scene s = unitSphere(m, 1, Vec3(4.0, 0.0, 5.0));
    const double c = 1.0 / std::sqrt(2.0);
    auto unblocked = [&](const Vec3& from) {
        const Vec3 d = glm::normalize(Vec3(0.0, 0.0, 1.0) - from);
        return child(shadeHit(s, Ray{from, d}, glm::length(Vec3(0.0, 0.0, 1.0) - from)), RayKind::Shadow).weight;
    };
    // From the mirror direction: Kd cos 45 + Ks (the highlight's peak)
    const Vec3 peak = unblocked(Vec3(-4.0, 0.0, 5.0));
    REQUIRE(peak.x == Approx(0.5 * c + 0.3).epsilon(1e-12));
    // 10 degrees off the mirror direction: Ks cos(10 deg)^10
    const double off = 10.0 * std::numbers::pi / 180.0;
    const Vec3 from(-4.0 * std::sqrt(2.0) * std::sin(0.25 * std::numbers::pi + off), 0.0,
                    1.0 + 4.0 * std::sqrt(2.0) * std::cos(0.25 * std::numbers::pi + off));
    REQUIRE(unblocked(from).x == Approx(0.5 * c + 0.3 * std::pow(std::cos(off), 10.0)).epsilon(1e-12));
    REQUIRE(unblocked(from).x < peak.x);
}

TEST_CASE("n lights each shine 1/sqrt(n) (Haines' SPD)", "[shading][physics]") {
    const Material m{Vec3(1.0), 0.8, 0.0, 0.0, 0.0, 1.0};
    const Ray down{Vec3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
    for (int n : {1, 4, 9}) {
        const Scene s = unitSphere(m, n);
        const std::vector<RayTask> c = shadeHit(s, down, 4.0);
        REQUIRE(c.size() == std::size_t(n));  // one shadow ray per light, no reflection (Ks = 0)
        for (const RayTask& t : c) REQUIRE(t.weight.x == Approx(0.8 / std::sqrt(double(n))).epsilon(1e-14));
    }
}

TEST_CASE("pp normals: the vertex normal at a vertex, blended inside", "[shading][physics]") {
    Scene s;
    s.addMaterial({});
    Polygon tri;
    const Vec3 n0 = glm::normalize(Vec3(0.0, 0.0, 1.0)), n1 = glm::normalize(Vec3(1.0, 0.0, 1.0)),
               n2 = glm::normalize(Vec3(0.0, 1.0, 1.0));
    REQUIRE_FALSE(makePolygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {n0, n1, n2}, tri).has_value());
    s.addPolygon(tri, 0);
    Polygon flat;
    REQUIRE_FALSE(makePolygon({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)}, {}, flat).has_value());
    s.addPolygon(flat, 0);
    s.finalize();
    REQUIRE(glm::length(s.normal(0, Vec3(0, 0, 0)) - n0) < 1e-12);
    REQUIRE(glm::length(s.normal(0, Vec3(1, 0, 0)) - n1) < 1e-12);
    REQUIRE(glm::length(s.normal(0, Vec3(0, 1, 0)) - n2) < 1e-12);
    // continuous at the vertices, and inside a unit blend of all three (all components > 0)
    REQUIRE(glm::length(s.normal(0, Vec3(1.0 - 1e-9, 1e-9, 0)) - n1) < 1e-6);
    for (const Vec3& p : {Vec3(0.5, 0, 0), Vec3(0.3, 0.3, 0), Vec3(0.1, 0.7, 0)}) {
        const Vec3 n = s.normal(0, p);
        REQUIRE(glm::length(n) == Approx(1.0).epsilon(1e-12));
        REQUIRE(n.z > 0.0);
        REQUIRE(n.x > 0.0);  // n1 contributes
        REQUIRE(n.y > 0.0);  // n2 contributes
    }
    // without vertex normals: the plane's normal everywhere
    REQUIRE(std::abs(std::abs(s.normal(1, Vec3(0.2, 0.2, 1)).z) - 1.0) < 1e-12);
}

TEST_CASE("project is the inverse of the eye rays", "[camera]") {
    Camera cam;
    cam.from = Vec3(1.0, 2.0, 6.0);
    cam.at = Vec3(0.0, 0.5, 0.0);
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.angle = 50.0;
    const RayGenerator gen(cam, 80, 60);
    // the point looked at is the image's centre: pixel x's eye ray passes through its
    // centre, so the middle of 80 pixels is x = 39.5
    const auto centre = gen.project(cam.at);
    REQUIRE(centre.has_value());
    REQUIRE(centre->x == Approx(39.5).epsilon(1e-12));
    REQUIRE(centre->y == Approx(29.5).epsilon(1e-12));
    Random rng(6);
    const Uniform u{0.0, 1.0};
    for (int i = 0; i < 1000; ++i) {
        const double x = 80.0 * u(rng), y = 60.0 * u(rng), t = 0.1 + 20.0 * u(rng);
        const Ray r = gen.primary(x, y);
        const auto p = gen.project(r.at(t));
        REQUIRE(p.has_value());
        REQUIRE(p->x == Approx(x).margin(1e-9));
        REQUIRE(p->y == Approx(y).margin(1e-9));
        // behind the eye: nothing
        REQUIRE_FALSE(gen.project(r.at(-t)).has_value());
    }
}
