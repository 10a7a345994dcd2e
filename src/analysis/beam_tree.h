#pragma once
/// \file
/// \brief The beam tree of an image, built after the fact from its rays, and coherence.
///
/// "Given the ray-trees for all the pixels in the scene, the beam-tree could be created
/// as a post-process by recursively merging adjacent rays if they intersect the same
/// surface" (Hanrahan 1986). Here: 4-adjacent pixels whose rays at the same ray-tree
/// path start on the same object and hit the same object (or nothing) are merged; each
/// connected group is one beam-tree node.
#include <cstddef>
#include <cstdint>
#include <memory>
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
/// Memory: the rays it was given (12 bytes each), in blocks of which each path's last may
/// be part-filled (at most one huge page, 2 MB, beyond its rays), plus one image of scratch
/// while it labels; never an image per ray-tree path. A render hears a million rays and more, so
/// recording one is an append into blocks that are never copied as they grow, and a merge
/// moves them.
class BeamTreeBuilder final : public TraceSink {
public:
    BeamTreeBuilder(int width, int height) : width_(width), height_(height) {}
    void onEvent(const TraceEvent& e) override;
    /// Records one ray directly: from a viewer's recorded events (SessionState::beams), or a
    /// hand-made image in tests.
    void record(int path, int pixel, int originObject, bool inside, int hitObject);
    BeamTreeStats build() const;
    /// Takes over the rays another builder of the same size recorded (other pixels), which
    /// is left empty; `pathMap[i]` is this builder's path id for the other's path `i`.
    void merge(BeamTreeBuilder&& other, const std::vector<int>& pathMap);
    /// Beam label of every pixel at one path (-1: no ray there); labels count from 0.
    std::vector<int> labels(int path) const;
    std::vector<int> paths() const;
    /// Rays held (for checking that memory follows the rays, not paths x pixels).
    std::int64_t storedRays() const { return rays_; }
    /// Rays the blocks have room for, filled or not (for checking that a path of few rays
    /// takes little memory).
    std::int64_t reservedRays() const;

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
    /// Rays reserved at once and filled in place: no ray is ever moved to make room.
    struct Block {
        struct Free {
            void operator()(Ray* p) const;
        };
        std::unique_ptr<Ray[], Free> rays;
        std::size_t size = 0, capacity = 0;  ///< size: of a sealed block (PathLog::filled())
        explicit Block(std::size_t n);
        const Ray* begin() const { return rays.get(); }
    };
    /// The rays of one path in recording order: small blocks, each twice the last (most
    /// paths hold few rays), then blocks of one huge page each where the system has them
    /// (every 4 KB page first touched costs a fault).
    struct PathLog {
        std::vector<Block> blocks;
        /// Where the next ray goes in the last block, and the end of its room (null: no
        /// block). The last block's count is `next` (its `size` is set when it is sealed):
        /// an append reads and writes this log only, not the block's header, which for
        /// hundreds of thousands of paths is one more cache miss a ray
        Ray* next = nullptr;
        Ray* end = nullptr;
        PathLog() = default;
        PathLog(PathLog&& o) noexcept
            : blocks(std::move(o.blocks)), next(std::exchange(o.next, nullptr)), end(std::exchange(o.end, nullptr)) {}
        PathLog& operator=(PathLog&& o) noexcept {
            blocks = std::move(o.blocks);
            next = std::exchange(o.next, nullptr);
            end = std::exchange(o.end, nullptr);
            return *this;
        }
        void push_back(const Ray& r) {
            if (next == end) grow();
            *next++ = r;
        }
        /// Rays in block `i`.
        std::size_t filled(std::size_t i) const {
            return i + 1 == blocks.size() ? std::size_t(next - blocks[i].begin()) : blocks[i].size;
        }
        std::size_t size() const;
        void grow();
        void resize(std::size_t n);  ///< n <= size(): forgets the rays after the first n
        void append(PathLog&& other);
        /// Sets the last block's size from `next` (before blocks are cut or moved).
        void seal() {
            if (!blocks.empty()) blocks.back().size = filled(blocks.size() - 1);
        }
        /// Points `next` and `end` into the last block, after its sealed size.
        void open();
    };
    /// The rays of one path sorted by pixel, the last recorded where a pixel has several.
    static std::vector<Ray> byPixel(const PathLog& rays);
    /// Labels the beams of one path (`rays` from byPixel); `index` is an image of -1 on
    /// entry and on return. Returns how many beams there are.
    int labelBeams(const std::vector<Ray>& rays, std::vector<int>& index, std::vector<int>& label) const;

    int width_, height_;
    std::int64_t rays_ = 0;
    std::vector<PathLog> rays_by_path_;  // by path id (a cache tree node)
};

}  // namespace rc
