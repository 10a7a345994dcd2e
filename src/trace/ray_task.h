#pragma once
/// \file
/// \brief A ray waiting to be traced: a link of some pixel's ray tree.
#include <cstdint>

#include "search/query.h"

namespace rc {

/// One ray of one pixel's ray tree. Whitted shading is linear, so the ray carries its
/// weight (the product of Ks and Kt along its path) and adds what it finds straight into
/// its pixel: no recursion, so rays can be traced in any order.
///
/// 120 bytes, kept on 64-byte lines: a task is exactly two cache lines. Breadth-first
/// order keeps a band's rays of a path for later, so every byte is written and read back
/// from memory once per ray.
struct alignas(64) RayTask {
    /// Its fields start as below, and nothing else is zeroed first (a task is made for
    /// every ray: `emplace_back()` would otherwise clear it all before setting it)
    RayTask() {}
    Query query;
    int pixel = 0;    ///< y * width + x
    int node = 0;     ///< its path in the cache tree (set by the render from `sample`)
    int depth = 1;    ///< the eye ray is depth 1
    /// Which sample it is among its parent's rays of its kind (shadow rays to the same
    /// light, glossy reflections), or its pixel sample for an eye ray
    int sample = 0;
    /// The key of its random numbers: a hash of the seed, the pixel, and every step of its
    /// path (kind, light, sample), so that what it draws never depends on the order of
    /// tracing, the thread, the cache or the search
    std::uint64_t key = 0;
    /// What this ray finds is multiplied by this. A shadow ray finds its light or nothing,
    /// so its weight is the light its pixel receives if nothing is in the way.
    Vec3 weight{1.0};
};
static_assert(sizeof(RayTask) == 128, "a ray task is two cache lines");

}  // namespace rc
