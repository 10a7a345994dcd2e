#pragma once
/// \file
/// \brief Distributed ray tracing (Cook, Porter and Carpenter 1984): pixel samples,
/// spherical lights and glossy reflection, with random numbers that are a pure function of
/// the seed, the pixel and the ray's path.
#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "scene/light.h"
#include "search/counters.h"

namespace rc {

/// What distributed ray tracing samples. The defaults trace one ray where Whitted's model
/// traces one: the image is then the classic one, bit for bit.
struct Sampling {
    int spp = 1;               ///< pixel samples, stratified and jittered (1: the pixel's own position)
    double lightRadius = 0.0;  ///< every light becomes a sphere of this radius (0: points)
    int shadowSamples = 1;     ///< shadow rays per light and hit, to points of its sphere (radius > 0 only)
    double glossDegrees = 0.0; ///< half-angle of the cone of glossy reflection directions (0: a mirror)
    int glossSamples = 1;      ///< reflection rays per hit inside that cone (gloss > 0 only)
    std::uint64_t seed = 1986; ///< the random numbers' seed
};

// [sampling-limits]
/// The documented limits of the sample counts and the gloss angle.
inline constexpr int kMaxSpp = 256;
inline constexpr int kMaxShadowSamples = 64;
inline constexpr int kMaxGlossSamples = 16;
inline constexpr double kMaxGlossDegrees = 90.0;
/// Glossy reflection branches at every depth: at most this many rays per pixel from it
/// (spp x gloss-samples^(depth - 1)).
inline constexpr double kMaxGlossRaysPerPixel = 1048576.0;  // 2^20
// [sampling-limits]

/// Why these settings cannot be rendered (negative, not finite, or over a limit), or
/// nothing when they can. `maxDepth` bounds the glossy branching.
std::optional<std::string> samplingError(const Sampling& s, int maxDepth);

/// The key of eye ray sample `sample` of pixel `pixel`.
std::uint64_t eyeKey(std::uint64_t seed, int pixel, int sample);
/// The key of a child ray: its parent's key and its step (kind, light, sample).
std::uint64_t childKey(std::uint64_t parent, RayKind kind, int light, int sample);

/// Offset of pixel sample `sample` of `spp` from the pixel's position, in [-0.5, 0.5)^2:
/// a jittered point of its cell in a grid of about sqrt(spp) x sqrt(spp) cells.
glm::dvec2 pixelSample(int spp, int sample, std::uint64_t key);

/// A point of the light's sphere seen from `p`: uniform on the disc through its centre,
/// facing `p` (the sphere's silhouette from far away). The disc lies inside the sphere,
/// so every shadow ray ends in the light's sphere.
Vec3 lightSample(const Light& light, const Vec3& p, std::uint64_t key);

/// A direction in the cone of half-angle `halfAngle` (radians) around unit `axis`,
/// uniform in solid angle.
Vec3 coneSample(const Vec3& axis, double halfAngle, std::uint64_t key);

}  // namespace rc
