#pragma once
/// \file
/// \brief Whitted shading, one ray at a time: what a ray adds to its pixel, and the rays
/// it spawns.
#include <vector>

#include "scene/scene.h"
#include "search/query.h"
#include "trace/distributed_sampling.h"
#include "trace/image_accumulator.h"
#include "trace/ray_task.h"

namespace rc {

/// Ray-tree limits and the shading model's constants.
struct ShadingOptions {
    int maxDepth = 5;       ///< the eye ray is depth 1, as in Haines' SPD
    double cutoff = 0.0;    ///< rays whose weight falls below this are not spawned (0: off)
    double ambient = 0.1;   ///< ambient light, times Kd and the surface colour
    Sampling sampling;      ///< distributed ray tracing (the defaults: none)
};

/// Shades the ray `task` whose nearest hit is `hit`: adds its local contribution to the
/// image and appends the rays it spawns (shadow rays to every light on the lit side,
/// reflection, refraction) to `children`. Each child says its step (kind, light, sample)
/// and carries its random-number key; its cache-tree path (`node`) is left at -1 for the
/// render to ask the cache tree for.
void shade(const Scene& scene, const RayTask& task, const Answer& hit, const ShadingOptions& opt,
           ImageAccumulator& image, std::vector<RayTask>& children);

/// The eye ray task of one pixel (pixel sample `sample`, random-number key `key`, and
/// weight `weight`: 1 / spp).
RayTask primaryTask(const Ray& ray, int pixel, int sample = 0, std::uint64_t key = 0, double weight = 1.0);
/// The same, made in `t`, a task just constructed, where it is kept (an order makes eye
/// rays by the band; a task returned by value and copied there is read back before its
/// own stores have landed).
void primaryTask(RayTask& t, const Ray& ray, int pixel, int sample, std::uint64_t key, double weight);

}  // namespace rc
