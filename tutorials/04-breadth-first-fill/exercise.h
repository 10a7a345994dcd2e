#pragma once
// Tutorial 04: the breadth-first fill.
#include <vector>

namespace tutorial {

// [declaration]
/// What the fill did with one pixel it took from its queue.
enum class Step {
    Seed,    ///< a complete search: a new region starts here and the cache is reloaded
    Answer,  ///< the cache answered it: its key equals the key of the region's seed
    Defer,   ///< the cache could not answer it: put aside, to be seeded or answered later
};

struct Visit {
    int pixel = 0;  ///< y * width + x
    Step step = Step::Seed;
};

/// Visits the pixels of a width x height image region by region, the way Hanrahan's
/// breadth-first search does for one ray-tree path. `key[pixel]` stands for what that
/// pixel's ray hits: the cache answers a pixel whose key equals the key of the current
/// region's seed. From every answered pixel, queue its 4-neighbours; a queued pixel the
/// cache cannot answer is deferred (record a Defer visit), never searched in the middle
/// of a region. Seed the next region only when the queue is empty.
///
/// The image is worked in bands of `band` scanlines (0: one band for the whole image),
/// top to bottom: no pixel of a band is visited before the band above is finished, so the
/// queue never holds more than `band` rows. Every pixel ends Seeded or Answered once.
std::vector<Visit> seedFill(int width, int height, int band, const std::vector<int>& key);
// [declaration]

}  // namespace tutorial
