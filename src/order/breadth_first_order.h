#pragma once
/// \file
/// \brief Breadth-first order: a seed fill (Smith's tint fill) over each ray-tree path.
#include <cstdint>
#include <utility>
#include <vector>

#include "order/ray_order.h"

namespace rc {

/// "In order to achieve one complete search per region the search should continue
/// two-dimensionally until a cache miss occurs" (Hanrahan 1986).
///
/// Works on a band of scanlines at a time, and within it on one ray-tree path at a time:
/// first every eye ray of the band, then the rays they spawned, path by path (the
/// breadth-first search of the ray tree). Each path is filled region by region: a seed
/// ray is traced (searching if it must), then its 4-neighbours are tried with the cheap
/// cache test only; those that hit extend the region, those that cannot be answered
/// cheaply are deferred and seed later regions, once the current one is finished.
///
/// A band of one scanline whose rays are all asked fully (no cheap tests, nothing
/// deferred) needs no fill: a region can only grow rightward, so the fill visits each
/// path's rays in pixel order, and the order walks them (see next()).
class BreadthFirstOrder final : public RayOrder {
public:
    /// Scanlines [rowBegin, rowEnd), `band` at a time (0: all).
    /// `samples` eye rays per pixel, each pixel sample an eye path of its own.
    BreadthFirstOrder(int width, int rowBegin, int rowEnd, int band, int samples, bool cheapTests, EyeMaker makeEye);
    OrderKind kind() const override { return OrderKind::BreadthFirst; }
    std::optional<Pick> next() override;
    void committed(const RayTask& task, Decision d, std::vector<RayTask>& children) override;
    void deferred(const RayTask& task) override;
    std::size_t queuePeak() const override { return peak_; }
    std::int64_t regions() const override { return regions_; }
    FrontierView frontier() const override;
    void roomAsNeeded() override { reserveBand_ = false; }
    std::unique_ptr<RayOrder> clone() const override { return std::make_unique<BreadthFirstOrder>(*this); }
    void restore(const RayOrder& saved) override { assignKeepingEye(*this, saved); }
    std::size_t heldBytes() const override;
    /// Scanlines per band.
    int band() const { return band_; }

private:
    friend class RayOrder;
    enum State : std::uint8_t { Absent, Unvisited, Queued, Deferred, Done };
    bool beginPath();
    void enqueueNeighbours(int local);
    /// The rays of path `node` (a cache tree node), made room for a band of them. Called for
    /// every ray spawned, so the common case (the path has room) is inline and making room
    /// is not
    std::vector<RayTask>& pathRays(int node) {
        if (std::size_t(node) < paths_.size() && paths_[std::size_t(node)].capacity() != 0)
            return paths_[std::size_t(node)];
        return newPath(node);
    }
    /// pathRays() for a path with no room yet: met for the first time, or restored from a
    /// checkpoint
    [[gnu::noinline]] std::vector<RayTask>& newPath(int node);
    /// The next untouched pixel of the grid from the scan on, or -1: the seed of a new region
    int nextUnvisited();
    std::optional<Pick> walk(const std::vector<RayTask>& tasks);
    /// The walk: the pixel its queue holds (the path's next ray, reached by the region), or -1
    int walkQueued() const;

    int width_, height_, band_, samples_;
    double invWidth_;  ///< 1 / width_
    bool cheapTests_;
    bool reserveBand_ = true;  ///< make room for a band of rays when a path is met (newPath)
    bool walks_;  ///< one scanline, every ray asked fully: the fill is a walk in pixel order
    EyeMaker makeEye_;
    int bandRow_ = 0;   ///< first scanline of the current band
    int nextRow_;       ///< first scanline of the next band
    // Rays of the current generation by path, the path being filled, and the next generation
    std::vector<int> generation_;  ///< paths (cache tree nodes) with rays in this generation
    std::size_t pathIndex_ = 0;
    bool pathActive_ = false;
    /// Rays by path (cache tree node): this generation's being traced, the next's spawned
    std::vector<std::vector<RayTask>> paths_;
    // Fill state of the active path, over the pixels of the band
    std::vector<int> slot_;
    std::vector<State> state_;
    /// By path, the band-local pixel of each of its rays (none for an eye path, whose rays
    /// are the band's pixels in order)
    std::vector<std::vector<int>> pixels_;
    /// First in, first out, in a vector that keeps its memory (a deque frees and takes a
    /// block every hundred-odd pixels: allocations that grow with the rays)
    struct PixelQueue {
        std::vector<int> items;
        std::size_t head = 0;
        bool empty() const { return head == items.size(); }
        std::size_t size() const { return items.size() - head; }
        int front() const { return items[head]; }
        void push_back(int pixel) { items.push_back(pixel); }
        void pop_front() {
            if (++head == items.size()) clear();
        }
        void clear() {
            items.clear();
            head = 0;
        }
    };
    PixelQueue queue_;
    PixelQueue pending_;
    int scan_ = 0;  ///< where the seed scan has reached: no pixel before it is still untouched
    /// The walk: the path's next ray, and the pixel its region reaches to (-1: none)
    std::size_t cursor_ = 0;
    int reach_ = -1;
    int inflight_ = -1;
    bool inflightSeed_ = false;
    std::size_t peak_ = 0;
    std::int64_t regions_ = 0;
};

}  // namespace rc
