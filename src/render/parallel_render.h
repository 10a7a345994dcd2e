#pragma once
/// \file
/// \brief Rendering on several threads: each thread traces its own scanlines with its own
/// cache tree, and the fixed-point image makes the result identical for any thread count.
#include <functional>
#include <memory>

#include "analysis/beam_tree.h"
#include "render/render_session.h"

namespace rc {

/// What a parallel render produced.
struct ParallelRun {
    ImageAccumulator image;
    Counters counters;              ///< summed over threads
    std::size_t queuePeak = 0;      ///< the largest of any thread
    std::int64_t regions = 0;       ///< summed over threads
    int paths = 0;                  ///< ray-tree paths met by any thread
    int threads = 1;
    bool completed = true;          ///< false when cancelled
};

/// Renders `options` on `threads` threads (0: one per core), splitting the image into
/// contiguous blocks of scanlines, one per thread. With `beams`, every ray is recorded
/// there too (the builder must be sized to the image). `progress` is called from the
/// calling thread with the fraction done; returning false cancels the render.
ParallelRun renderParallel(std::shared_ptr<const Scene> scene, const RenderOptions& options, int threads,
                           BeamTreeBuilder* beams = nullptr,
                           const std::function<bool(double)>& progress = {});

}  // namespace rc
