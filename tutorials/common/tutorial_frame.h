#pragma once
// A check's presentation of its recorded cases: each run shows the student's code every
// case in a frame of the run's own, drawn from a seed (std::random_device, or
// $TUTORIAL_NN_SEED to repeat a run; a check prints it with every failure), so that the
// numbers the code sees are never the recorded case's; the expected answer is the recorded
// one, mapped through the frame.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

#include <glm/geometric.hpp>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "tutorial_random.h"

namespace tutorial {

/// The run's seed: $`variable` when set (to repeat a run), else std::random_device.
inline std::uint64_t runSeed(const char* variable) {
    if (const char* given = std::getenv(variable); given && *given) return std::uint64_t(std::strtoull(given, nullptr, 10));
    std::random_device device;
    return (std::uint64_t(device()) << 32) ^ std::uint64_t(device());
}

/// A similarity of space: x -> shift + scale * rotation * x, the scale a power of two (so
/// that scaling, and scaling back, round nothing).
struct Frame {
    rc::Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};  // the rotation's columns
    rc::Vec3 shift{0.0};
    double scale = 1.0;

    rc::Vec3 turn(const rc::Vec3& v) const { return v.x * x + v.y * y + v.z * z; }
    rc::Vec3 point(const rc::Vec3& p) const { return shift + scale * turn(p); }
    rc::Sphere sphere(const rc::Sphere& s) const { return {point(s.c), scale * s.r}; }
    /// A ray's origin moved, its direction turned and its length kept: a distance t along
    /// the ray becomes scale * t.
    rc::Ray ray(const rc::Ray& r) const {
        rc::Ray out = r;
        out.o = point(r.o);
        out.d = turn(r.d);
        return out;
    }
};

/// A uniform random rotation: a frame with no shift and scale 1.
inline Frame randomRotation(Random& rnd) {
    Frame f;
    f.x = rnd.direction();
    do f.y = glm::cross(f.x, rnd.direction());
    while (glm::length(f.y) < 0.1);
    f.y = glm::normalize(f.y);
    f.z = glm::cross(f.x, f.y);
    return f;
}

/// A random frame: a uniform rotation, a shift in [-`reach`, `reach`]^3 and a scale 2^k, k
/// in [-`octaves`, `octaves`].
inline Frame randomFrame(Random& rnd, double reach, int octaves) {
    Frame f = randomRotation(rnd);
    f.shift = rnd.inBox(reach);
    f.scale = std::ldexp(1.0, rnd.index(2 * octaves + 1) - octaves);
    return f;
}

}  // namespace tutorial
