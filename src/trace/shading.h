#pragma once
/// \file
/// \brief Whitted shading, one ray at a time: what a ray adds to its pixel, and the rays
/// it spawns.
#include <vector>

#include "search/cache_tree.h"
#include "trace/image_accumulator.h"
#include "trace/ray_task.h"

namespace rc {

/// Ray-tree limits and the shading model's constants.
struct ShadingOptions {
    int maxDepth = 5;       ///< the eye ray is depth 1, as in Haines' SPD
    double cutoff = 0.0;    ///< rays whose weight falls below this are not spawned (0: off)
    double ambient = 0.1;   ///< ambient light, times Kd and the surface colour
};

/// Shades the ray `task` whose nearest hit is `hit`: adds its local contribution to the
/// image and appends the rays it spawns (shadow rays to every light on the lit side,
/// reflection, refraction) to `children`, making their cache-tree paths as needed.
void shade(const Scene& scene, const RayTask& task, const Answer& hit, const ShadingOptions& opt,
           CacheTree& paths, ImageAccumulator& image, std::vector<RayTask>& children);

/// The eye ray task of one pixel.
RayTask primaryTask(const Ray& ray, int pixel);

}  // namespace rc
