// The stable ray-sphere roots against a reference computed apart from the library, in long
// double (the instructor's: the reference forms the stable discriminant, part of tutorial 06's
// answer, so the student edition leaves tests/instructor/ out, scripts/student_edition.py).
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "../uniform.h"

using namespace rc;

namespace {
// Nearest positive root in long double, from the same quadratic written out directly
long double referenceRoot(const Ray& ray, const Sphere& s, bool far) {
    const long double fx = (long double)ray.o.x - s.c.x, fy = (long double)ray.o.y - s.c.y,
                      fz = (long double)ray.o.z - s.c.z;
    const long double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
    const long double a = dx * dx + dy * dy + dz * dz;
    const long double b = fx * dx + fy * dy + fz * dz;
    // perpendicular offset, in long double
    const long double lx = fx - b / a * dx, ly = fy - b / a * dy, lz = fz - b / a * dz;
    const long double disc = (long double)s.r * s.r - (lx * lx + ly * ly + lz * lz);
    if (disc < 0) return -1;
    const long double root = std::sqrt(disc * a);
    return far ? (-b + root) / a : (-b - root) / a;
}
}  // namespace

TEST_CASE("stable roots match a long double reference on random rays", "[intersection]") {
    Random rng(7);
    const Uniform u{-1.0, 1.0};
    double worst = 0.0;
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const double scale = std::pow(10.0, 6.0 * u(rng));  // radii from 1e-6 to 1e6
        const Sphere s{Vec3(u(rng), u(rng), u(rng)) * scale, scale * (0.1 + std::abs(u(rng)))};
        const double dist = s.r * std::pow(10.0, 3.0 * std::abs(u(rng)));  // near or far away
        Ray ray{s.c + randomUnit(rng) * (s.r + dist), Vec3(0.0)};
        // aim at a random point of the sphere's disc, sometimes grazing
        const Vec3 target = s.c + randomUnit(rng) * s.r * (i % 4 == 0 ? 0.999999 : std::abs(u(rng)));
        ray.d = glm::normalize(target - ray.o);
        const SphereRoots r = sphereRootsStable(ray, s);
        const long double ref = referenceRoot(ray, s, false);
        if (ref < 0) continue;
        REQUIRE(r.hit);
        ++hits;
        const double rel = double(std::abs((r.t0 - ref) / ref));
        worst = std::max(worst, rel);
    }
    INFO("worst relative error " << worst);
    REQUIRE(hits > 10000);
    REQUIRE(worst < 1e-9);
}

TEST_CASE("textbook roots lose the small far sphere the stable form keeps", "[intersection]") {
    // A sphere of radius 1e-3 seen from 1e6 away: b*b - c cancels catastrophically
    const Sphere s{Vec3(0.0, 0.0, -1e6), 1e-3};
    const Ray ray{Vec3(0.0), glm::normalize(Vec3(0.0, 0.9e-3 / 1e6, -1.0))};
    const SphereRoots stable = sphereRootsStable(ray, s);
    const SphereRoots textbook = sphereRootsTextbook(ray, s);
    const long double ref = referenceRoot(ray, s, false);
    REQUIRE(stable.hit);
    REQUIRE(std::abs((stable.t0 - ref) / ref) < 1e-12);
    const bool textbookWrong = !textbook.hit || std::abs((textbook.t0 - ref) / ref) > 1e-9 ||
                               std::abs(((textbook.t1 - textbook.t0) - 2 * 0.4359e-3)) > 1e-4;
    REQUIRE(textbookWrong);
}

