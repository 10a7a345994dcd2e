#include "order/breadth_first_order.h"

#include <algorithm>
#include <cstring>

namespace rc {

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

std::optional<Pick> BreadthFirstOrder::next() {
    for (;;) {
        if (!pathActive_ && !beginPath()) return std::nullopt;
        const std::vector<RayTask>& tasks = paths_[generation_[pathIndex_]];
        if (walks_) {
            if (auto pick = walk(tasks)) return pick;
            pathActive_ = false;
            continue;
        }
        // [bfs-next]
        // Keep filling the current region with cheap tests only
        if (!queue_.empty()) {
            inflight_ = queue_.front();
            queue_.pop_front();
            inflightSeed_ = false;
            return Pick{&tasks[std::size_t(slot_[inflight_])], cheapTests_ ? LookupMode::CheapOnly : LookupMode::Full};
        }
        // The region is finished: a deferred ray, else the next untouched one, seeds the next
        int seed = -1;
        while (!pending_.empty() && seed < 0) {
            if (state_[pending_.front()] == Deferred) seed = pending_.front();
            pending_.pop_front();
        }
        if (seed < 0) seed = nextUnvisited();
        // [bfs-next]
        if (seed < 0) {
            // Every ray of this path is traced: its pixels leave the fill grid
            const std::vector<int>& local = pixels_[std::size_t(generation_[pathIndex_])];
            if (local.empty()) std::fill(state_.begin(), state_.end(), Absent);
            for (int at : local) state_[std::size_t(at)] = Absent;
            pathActive_ = false;
            continue;
        }
        ++regions_;
        state_[seed] = Queued;
        inflight_ = seed;
        inflightSeed_ = true;
        return Pick{&tasks[std::size_t(slot_[seed])], LookupMode::Full};
    }
}

std::optional<Pick> BreadthFirstOrder::walk(const std::vector<RayTask>& tasks) {
    // [bfs-walk]
    // One scanline, no ray deferred: a region grows only rightward (its left neighbour was
    // traced before it), so the fill reduces to the path's rays in pixel order, the order
    // they were spawned in. A ray seeds a new region unless the last one reached its pixel
    if (cursor_ == tasks.size()) return std::nullopt;
    const RayTask& task = tasks[cursor_];
    inflight_ = task.pixel;
    inflightSeed_ = task.pixel != reach_;
    regions_ += inflightSeed_;
    return Pick{&task, LookupMode::Full};
    // [bfs-walk]
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
    if (rays.capacity() == 0) {
        const std::size_t band = std::size_t(nextRow_ - bandRow_) * width_;
        rays.reserve(band);
        if (!walks_) pixels_[std::size_t(node)].reserve(band);
    }
    return rays;
}

int BreadthFirstOrder::nextUnvisited() {
    // [bfs-seed-scan]
    // The grid in pixel order, a byte a pixel: memchr looks at many at once
    const std::size_t from = std::size_t(scan_), size = state_.size();
    if (from >= size) return -1;
    const void* found = std::memchr(state_.data() + from, Unvisited, size - from);
    if (!found) {
        scan_ = int(size);
        return -1;
    }
    const int seed = int(static_cast<const State*>(found) - state_.data());
    scan_ = seed + 1;
    return seed;
    // [bfs-seed-scan]
}

int BreadthFirstOrder::walkQueued() const {
    // The fill's queue would hold the next pixel, if the region reaches it and it is on the path
    const std::vector<RayTask>& tasks = paths_[std::size_t(generation_[pathIndex_])];
    return reach_ >= 0 && cursor_ < tasks.size() && tasks[cursor_].pixel == reach_ ? reach_ : -1;
}

void BreadthFirstOrder::enqueueNeighbours(int local) {
    // The pixel's row and column without an integer division (a division per ray costs
    // more than the rest of this function): (local + 1/2) / width is an exact enough quotient
    const int y = int((local + 0.5) * invWidth_), x = local - y * width_;
    const int rows = nextRow_ - bandRow_;
    // Plain pointers: a state is a byte, and a store through it could change any member,
    // which the compiler would then load again after every store
    State* const state = state_.data();
    const int* const slot = slot_.data();
    const RayTask* const tasks = paths_[generation_[pathIndex_]].data();
    auto visit = [&](int q) {
        if (state[q] != Unvisited && state[q] != Deferred) return;
        state[q] = Queued;
        queue_.push_back(q);
        // Its ray is traced soon: start fetching it now
        const char* task = reinterpret_cast<const char*>(tasks + slot[q]);
        for (std::size_t line = 0; line < sizeof(RayTask); line += 64) __builtin_prefetch(task + line);
    };
    if (x > 0) visit(local - 1);
    if (x + 1 < width_) visit(local + 1);
    if (y > 0) visit(local - width_);
    if (y + 1 < rows) visit(local + width_);
    peak_ = std::max(peak_, queue_.size());
}

void BreadthFirstOrder::committed(const RayTask&, Decision d, std::vector<RayTask>& children) {
    for (RayTask& c : children) {
        std::vector<RayTask>& path = pathRays(c.node);
        // Its pixel in the band, kept apart for the fill grid (not in the walk, which needs no grid)
        if (!walks_) pixels_[std::size_t(c.node)].push_back(c.pixel - bandRow_ * width_);
        path.push_back(std::move(c));
    }
    // [bfs-extend]
    // A seed, or a ray the cache answered with the region's object, extends the region
    const bool extends = inflightSeed_ || d == Decision::Hit || d == Decision::Uncached;
    if (walks_) {
        // along the scanline only: to the next pixel
        ++cursor_;
        reach_ = extends ? inflight_ + 1 : -1;
        // The queue holds at most that pixel
        if (peak_ == 0 && walkQueued() >= 0) peak_ = 1;
        return;
    }
    state_[inflight_] = Done;
    if (extends) enqueueNeighbours(inflight_);
    // [bfs-extend]
}

void BreadthFirstOrder::deferred(const RayTask&) {
    state_[inflight_] = Deferred;
    pending_.push_back(inflight_);
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
