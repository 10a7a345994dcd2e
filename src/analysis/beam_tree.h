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
#include <utility>
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
/// Memory: the rays it was given (12 bytes each) plus one image of scratch while it
/// labels, never an image per ray-tree path.
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
    /// Rays held (for checking that memory follows the rays, not paths x pixels).
    std::int64_t storedRays() const { return rays_; }

    /// How many rays each path held at some moment: the rays are a log that only grows,
    /// so a checkpoint of a stepping render keeps its length.
    struct Mark {
        std::int64_t rays = 0;
        std::vector<std::pair<int, std::size_t>> paths;  ///< (path, rays recorded at it)
    };
    Mark mark() const;
    /// Forgets the rays recorded after `m` (a mark of this builder, taken before them).
    void rollback(const Mark& m);

private:
    /// One recorded ray: its pixel and its beam key (origin object and side; hit object).
    struct Ray {
        std::int32_t pixel;
        std::uint32_t origin;
        std::uint32_t hit;
        bool sameBeam(const Ray& o) const { return origin == o.origin && hit == o.hit; }
    };
    /// The rays of one path sorted by pixel, the last recorded where a pixel has several.
    static std::vector<Ray> byPixel(const std::vector<Ray>& rays);
    /// Labels the beams of one path (`rays` from byPixel); `index` is an image of -1 on
    /// entry and on return. Returns how many beams there are.
    int labelBeams(const std::vector<Ray>& rays, std::vector<int>& index, std::vector<int>& label) const;

    int width_, height_;
    std::int64_t rays_ = 0;
    std::unordered_map<int, std::vector<Ray>> rays_by_path_;  // path -> rays in recording order
};

}  // namespace rc
