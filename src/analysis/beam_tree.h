#pragma once
/// \file
/// \brief The beam tree of an image, built after the fact from its rays, and coherence.
///
/// "Given the ray-trees for all the pixels in the scene, the beam-tree could be created
/// as a post-process by recursively merging adjacent rays if they intersect the same
/// surface" (Hanrahan 1986). Here: 4-adjacent pixels whose rays at the same ray-tree
/// path start on the same object and hit the same object (or nothing) are merged; each
/// connected group is one beam-tree node.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "trace/trace_event.h"

namespace rc {

/// Size of the beam tree and the paper's coherence.
struct BeamTreeStats {
    std::int64_t nodes = 0;             ///< beam-tree size
    double averageRayTreeSize = 0.0;    ///< rays per pixel
    double coherence = 0.0;             ///< averageRayTreeSize / nodes
};

/// Collects (path, origin, hit) per pixel from trace events; `build()` labels beams.
class BeamTreeBuilder final : public TraceSink {
public:
    BeamTreeBuilder(int width, int height) : width_(width), height_(height) {}
    void onEvent(const TraceEvent& e) override;
    /// Records one ray directly (for hand-made images in tests).
    void record(int path, int pixel, int originObject, bool inside, int hitObject);
    BeamTreeStats build() const;
    /// Takes in the rays another builder of the same size recorded (other pixels);
    /// `pathMap[i]` is this builder's path id for the other's path `i`.
    void merge(const BeamTreeBuilder& other, const std::vector<int>& pathMap);
    /// Beam label of every pixel at one path (-1: no ray there); labels count from 0.
    std::vector<int> labels(int path) const;
    std::vector<int> paths() const;

private:
    int width_, height_;
    std::int64_t rays_ = 0;
    std::unordered_map<int, std::vector<std::uint64_t>> keys_;  // path -> key per pixel
};

}  // namespace rc
