#pragma once
/// \file
/// \brief Whether the samples of distributed ray tracing share the cache entry of their path.
#include <cstdint>

namespace rc {

/// How the samples of distributed ray tracing (pixel samples, shadow-ray samples, glossy
/// samples) share cache entries. Every sample always has a path of its own (orders and the
/// beam tree need one ray per path and pixel); the choice is whether its path has an entry
/// of its own.
///
/// In scanline and progressive order the samples of one pixel follow each other, and a
/// shared entry answers sample k with what sample k - 1 found a moment before; an entry per
/// sample last saw the neighbouring pixel's sample k. Breadth-first order fills one path at
/// a time, so sample k's fill starts where sample k - 1's ended: the two choices come out
/// alike. Shared is the default; `raycache coherence --sample-entries per-sample|shared`
/// measures them.
enum class SampleEntries : std::uint8_t {
    PerSample,  ///< one entry per (path, sample index): sample k of a pixel meets sample k of its neighbour
    Shared,     ///< the samples of a path share one entry: sample k meets sample k - 1 of the same pixel
};

}  // namespace rc
