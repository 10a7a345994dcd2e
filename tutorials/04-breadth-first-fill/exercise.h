#pragma once
// Tutorial 04: the breadth-first fill.
#include <vector>

namespace tutorial {

// [declaration]
/// One pixel visited by the fill. `seed`: the visit starts a new region, so the cache
/// is reloaded with this pixel's key (a complete search); otherwise the pixel is
/// answered by the cache, which holds the key of the region's seed.
struct Visit {
    int pixel = 0;  ///< y * width + x
    bool seed = false;
};

/// Visits every pixel of a width x height image once, region by region, the way
/// Hanrahan's breadth-first search does for one ray-tree path. `key[pixel]` stands for
/// what that pixel's ray hits: the cache answers a pixel whose key equals the key of the
/// current region's seed. Continue from every answered pixel to its 4-neighbours until
/// the region cannot grow, and only then seed the next region.
std::vector<Visit> seedFill(int width, int height, const std::vector<int>& key);
// [declaration]

}  // namespace tutorial
