#include "order/breadth_first_order.h"

#include <algorithm>

namespace rc {

// The fill itself (next(), committed(), deferred() and their helpers): order/seed_fill.cpp,
// tutorial 04's hole

BreadthFirstOrder::BreadthFirstOrder(int width, int rowBegin, int rowEnd, int band, int samples, bool cheapTests,
                                     EyeMaker makeEye)
    : width_(width), height_(rowEnd), band_(band > 0 ? std::min(band, rowEnd - rowBegin) : rowEnd - rowBegin),
      samples_(samples), invWidth_(1.0 / width), cheapTests_(cheapTests), walks_(band_ == 1 && !cheapTests),
      makeEye_(std::move(makeEye)),
      nextRow_(rowBegin) {}

bool BreadthFirstOrder::beginPath() {
    if (pathIndex_ < generation_.size()) ++pathIndex_;
    if (pathIndex_ >= generation_.size()) {
        // The next generation of the ray tree; when none is left, the next band. A path
        // belongs to one generation (its depth), so one buffer per path serves both the
        // rays being traced and those being spawned, and keeps its memory from band to band
        for (int node : generation_) {
            paths_[node].clear();
            pixels_[node].clear();
        }
        generation_.clear();
        for (int node = 0; node < int(paths_.size()); ++node)
            if (!paths_[node].empty()) generation_.push_back(node);
        pathIndex_ = 0;
        if (generation_.empty()) {
            if (nextRow_ >= height_) return false;
            bandRow_ = nextRow_;
            nextRow_ = std::min(height_, bandRow_ + band_);
            // Each pixel sample's eye rays are a path of their own
            for (int k = 0; k < samples_; ++k) {
                RayTask first;
                makeEye_(bandRow_ * width_, k, first);
                std::vector<RayTask>& eyes = pathRays(first.node);
                for (int p = bandRow_ * width_; p < nextRow_ * width_; ++p) makeEye_(p, k, eyes.emplace_back());
                generation_.push_back(first.node);
            }
        }
    }
    pathActive_ = true;
    if (walks_) {
        cursor_ = 0;
        reach_ = -1;
        return true;
    }
    // The fill grid of this path: which pixels of the band have a ray on it, and which of
    // the path's rays each holds. Only the path's own pixels are touched (a deep path may
    // hold a handful of rays), and they are read from the path's list of pixels, not from
    // its rays: a ray was written a generation ago and has left the nearer caches
    const std::size_t pixels = std::size_t(nextRow_ - bandRow_) * width_;
    if (state_.size() != pixels) {
        state_.assign(pixels, Absent);
        slot_.assign(pixels, -1);
    }
    // [bfs-grid]
    const int node = generation_[pathIndex_];
    const std::vector<int>& local = pixels_[std::size_t(node)];
    // An eye path holds the band's pixels in order (it has no list: its rays were made here)
    const int rays = int(paths_[std::size_t(node)].size());
    for (int i = 0; i < rays; ++i) {
        const int at = local.empty() ? i : local[std::size_t(i)];
        slot_[std::size_t(at)] = i;
        state_[std::size_t(at)] = Unvisited;
    }
    // [bfs-grid]
    queue_.clear();
    pending_.clear();
    scan_ = 0;
    return true;
}

std::vector<RayTask>& BreadthFirstOrder::newPath(int node) {
    if (node >= int(paths_.size())) {
        paths_.resize(std::size_t(node) + 1);
        pixels_.resize(std::size_t(node) + 1);
    }
    std::vector<RayTask>& rays = paths_[std::size_t(node)];
    // A path has at most one ray per pixel: room for a band at once, so neither it nor its
    // list of pixels ever grows by copying into fresh memory (each new page is a fault; at
    // 512x512, a third of committed()'s time)
    if (rays.capacity() == 0 && reserveBand_) {
        const std::size_t band = std::size_t(nextRow_ - bandRow_) * width_;
        rays.reserve(band);
        if (!walks_) pixels_[std::size_t(node)].reserve(band);
    }
    return rays;
}

FrontierView BreadthFirstOrder::frontier() const {
    FrontierView f;
    if (!pathActive_) return f;
    f.path = generation_[pathIndex_];
    f.region = regions_;
    if (walks_) {
        if (const int pixel = walkQueued(); pixel >= 0) f.queued.push_back(pixel);
        return f;
    }
    const int base = bandRow_ * width_;
    for (std::size_t i = queue_.head; i < queue_.items.size(); ++i) f.queued.push_back(base + queue_.items[i]);
    for (int q = 0; q < int(state_.size()); ++q)
        if (state_[q] == Deferred) f.deferred.push_back(base + q);
    return f;
}

std::size_t BreadthFirstOrder::heldBytes() const {
    std::size_t tasks = 0;
    for (const std::vector<RayTask>& p : paths_) tasks += p.size();
    std::size_t pixels = 0;
    for (const std::vector<int>& p : pixels_) pixels += p.size();
    return tasks * sizeof(RayTask) + paths_.size() * (sizeof(std::vector<RayTask>) + sizeof(std::vector<int>)) +
           (pixels + generation_.size() + slot_.size() + queue_.items.size() + pending_.items.size()) *
               sizeof(int) +
           state_.size();
}

}  // namespace rc
