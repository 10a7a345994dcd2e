#pragma once
/// \file
/// \brief Image error against run time: RMSE of a partial render against the final image
/// as rendering proceeds, and of supersampled images against a high-sample reference.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "render/render_session.h"

namespace rc {

/// An image as linear RGB values, one per pixel.
using LinearImage = std::vector<Vec3>;

/// The accumulator's values.
LinearImage linearImage(const ImageAccumulator& image);

/// Root mean square difference of the two images over every pixel and channel, each
/// value clamped to [0, 1] first (what a display shows).
double rmse(const LinearImage& a, const LinearImage& b);
double rmse(const ImageAccumulator& a, const LinearImage& b);

/// One sample of a render in progress.
struct ProgressPoint {
    std::int64_t steps = 0;  ///< rays traced
    double seconds = 0;      ///< render time so far (measuring excluded)
    double rmse = 0;         ///< of the partial image against the final one
};

/// A render sampled `samples` times (evenly in rays traced) as it proceeds: RMSE of the
/// partial image against `final`. `totalSteps` is the number of rays the render traces
/// (any earlier render of the same scene and options says it).
std::vector<ProgressPoint> traceProgress(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                                         const LinearImage& final, std::int64_t totalSteps, int samples);

/// `n` jitter offsets in [-0.5, 0.5)^2: the Halton (2, 3) sequence shifted by a seeded
/// random vector (a Cranley-Patterson rotation), so every prefix is well spread.
std::vector<glm::dvec2> jitterOffsets(int n, std::uint64_t seed);

/// A regular `k` x `k` grid of offsets at the centres of the pixel's sub-squares.
std::vector<glm::dvec2> gridOffsets(int k);

/// The average of renders at the given pixel offsets (and its render time).
LinearImage averageImage(std::shared_ptr<const Scene> scene, RenderOptions options,
                         const std::vector<glm::dvec2>& offsets, double* seconds = nullptr);

/// One point of a supersampling curve.
struct SupersamplePoint {
    int spp = 0;
    double seconds = 0;  ///< render time of all samples so far
    double rmse = 0;     ///< of their average against the reference
};

/// Supersampling one sample at a time, so that several configurations can take turns
/// (and share the machine's ups and downs alike).
class SuperSampler {
public:
    SuperSampler(std::shared_ptr<const Scene> scene, RenderOptions options, const LinearImage& reference);
    /// Renders one more sample at `offset`; at 1, 2, 4, ... samples and when `last`,
    /// records a point.
    void add(const glm::dvec2& offset, bool last = false);
    const std::vector<SupersamplePoint>& points() const { return points_; }

private:
    std::shared_ptr<const Scene> scene_;
    RenderOptions options_;
    const LinearImage& reference_;
    LinearImage sum_;
    int samples_ = 0;
    double seconds_ = 0.0;
    std::vector<SupersamplePoint> points_;
};

/// Renders the jittered samples one by one and reports, at 1, 2, 4, ... and
/// offsets.size() samples, the RMSE of their average against `reference`.
std::vector<SupersamplePoint> superSample(std::shared_ptr<const Scene> scene, RenderOptions options,
                                          const std::vector<glm::dvec2>& offsets, const LinearImage& reference);

}  // namespace rc
