#include "trace/distributed_sampling.h"
#include "geometry/portable_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "scene/random.h"

namespace rc {

namespace {
/// Two unit vectors that make a right-handed frame with unit `w`.
void frame(const Vec3& w, Vec3& u, Vec3& v) {
    const Vec3 a = std::abs(w.x) < 0.6 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    u = glm::normalize(glm::cross(a, w));
    v = glm::cross(w, u);
}
}  // namespace

std::optional<std::string> samplingError(const Sampling& s, int maxDepth) {
    auto count = [](const char* what, int n, int limit) -> std::optional<std::string> {
        if (n < 1 || n > limit)
            return std::string(what) + " must be a whole number from 1 to " + std::to_string(limit) + ", not " +
                   std::to_string(n);
        return std::nullopt;
    };
    if (auto e = count("--spp", s.spp, kMaxSpp)) return e;
    if (auto e = count("--shadow-samples", s.shadowSamples, kMaxShadowSamples)) return e;
    if (auto e = count("--gloss-samples", s.glossSamples, kMaxGlossSamples)) return e;
    if (!std::isfinite(s.lightRadius) || s.lightRadius < 0.0)
        return "--light-radius must be a finite number >= 0";
    if (!std::isfinite(s.glossDegrees) || s.glossDegrees < 0.0 || s.glossDegrees > kMaxGlossDegrees)
        return "--gloss must be a number of degrees from 0 to 90";
    if (s.glossDegrees > 0.0 && s.glossSamples > 1) {
        const double rays = double(s.spp) * std::pow(double(s.glossSamples), double(std::max(0, maxDepth - 1)));
        if (rays > kMaxGlossRaysPerPixel)
            return "--spp x --gloss-samples^(depth - 1) = " + std::to_string(std::llround(std::min(rays, 1e18))) +
                   " glossy rays per pixel is over the limit of 2^20: lower --gloss-samples, --spp or --depth";
    }
    return std::nullopt;
}

// [sample-keys]
std::uint64_t eyeKey(std::uint64_t seed, int pixel, int sample) {
    return mixKey(mixKey(mixKey(seed, std::uint64_t(pixel)), std::uint64_t(RayKind::Primary)), std::uint64_t(sample));
}

std::uint64_t childKey(std::uint64_t parent, RayKind kind, int light, int sample) {
    const std::uint64_t step = (std::uint64_t(kind) << 56) ^ (std::uint64_t(std::uint32_t(light + 1)) << 24) ^
                               std::uint64_t(std::uint32_t(sample));
    return mixKey(parent, step);
}
// [sample-keys]

glm::dvec2 pixelSample(int spp, int sample, std::uint64_t key) {
    // [pixel-sample]
    // Stratified: nx x ny cells cover the pixel, sample s jitters inside cell s
    const int nx = int(std::ceil(std::sqrt(double(spp))));
    const int ny = (spp + nx - 1) / nx;
    const int i = sample % nx, j = sample / nx;
    return {(i + hashedUnit(key, 0)) / nx - 0.5, (j + hashedUnit(key, 1)) / ny - 0.5};
    // [pixel-sample]
}

Vec3 lightSample(const Light& light, const Vec3& p, std::uint64_t key) {
    // [light-sample]
    // Uniform on the disc of the light's radius through its centre, facing p
    const Vec3 toP = p - light.position;
    const double len = glm::length(toP);
    const Vec3 w = len > 0.0 ? toP / len : Vec3(0.0, 0.0, 1.0);
    Vec3 u, v;
    frame(w, u, v);
    const double r = light.radius * std::sqrt(hashedUnit(key, 0));
    const double phi = 2.0 * std::numbers::pi * hashedUnit(key, 1);
    return light.position + r * (pm::cos(phi) * u + pm::sin(phi) * v);
    // [light-sample]
}

Vec3 coneSample(const Vec3& axis, double halfAngle, std::uint64_t key) {
    // [cone-sample]
    // cos(theta) uniform in [cos(alpha), 1]: uniform in solid angle over the cone
    const double cosT = 1.0 - hashedUnit(key, 0) * (1.0 - pm::cos(halfAngle));
    const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
    const double phi = 2.0 * std::numbers::pi * hashedUnit(key, 1);
    Vec3 u, v;
    frame(axis, u, v);
    return glm::normalize(cosT * axis + sinT * (pm::cos(phi) * u + pm::sin(phi) * v));
    // [cone-sample]
}

}  // namespace rc
