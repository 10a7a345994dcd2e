#include "order/breadth_first_order.h"

#include <algorithm>

namespace rc {

BreadthFirstOrder::BreadthFirstOrder(int width, int rowBegin, int rowEnd, int band, bool cheapTests,
                                     EyeMaker makeEye)
    : width_(width), height_(rowEnd), band_(band > 0 ? std::min(band, rowEnd - rowBegin) : rowEnd - rowBegin),
      cheapTests_(cheapTests), makeEye_(std::move(makeEye)), nextRow_(rowBegin) {}

bool BreadthFirstOrder::beginPath() {
    if (pathIndex_ < generation_.size()) ++pathIndex_;
    if (pathIndex_ >= generation_.size()) {
        // The next generation of the ray tree; when none is left, the next band
        generation_.clear();
        for (int node = 0; node < int(nextGeneration_.size()); ++node) {
            if (nextGeneration_[node].empty()) continue;
            generation_.emplace_back(node, std::move(nextGeneration_[node]));
            nextGeneration_[node].clear();
        }
        pathIndex_ = 0;
        if (generation_.empty()) {
            if (nextRow_ >= height_) return false;
            bandRow_ = nextRow_;
            nextRow_ = std::min(height_, bandRow_ + band_);
            std::vector<RayTask> eyes;
            eyes.reserve(std::size_t(nextRow_ - bandRow_) * width_);
            for (int p = bandRow_ * width_; p < nextRow_ * width_; ++p) eyes.push_back(makeEye_(p));
            generation_.emplace_back(0, std::move(eyes));
        }
    }
    // The fill grid of this path: which pixels of the band have a ray on it
    const std::size_t pixels = std::size_t(nextRow_ - bandRow_) * width_;
    slot_.assign(pixels, -1);
    state_.assign(pixels, Absent);
    const std::vector<RayTask>& tasks = generation_[pathIndex_].second;
    for (int i = 0; i < int(tasks.size()); ++i) {
        const int local = tasks[i].pixel - bandRow_ * width_;
        slot_[local] = i;
        state_[local] = Unvisited;
    }
    queue_.clear();
    pending_.clear();
    scan_ = 0;
    pathActive_ = true;
    return true;
}

std::optional<Pick> BreadthFirstOrder::next() {
    for (;;) {
        if (!pathActive_ && !beginPath()) return std::nullopt;
        const std::vector<RayTask>& tasks = generation_[pathIndex_].second;
        // [bfs-next]
        // Keep filling the current region with cheap tests only
        if (!queue_.empty()) {
            inflight_ = queue_.front();
            queue_.pop_front();
            inflightSeed_ = false;
            return Pick{tasks[slot_[inflight_]], cheapTests_ ? LookupMode::CheapOnly : LookupMode::Full};
        }
        // The region is finished: a deferred ray, else the next untouched one, seeds the next
        int seed = -1;
        while (!pending_.empty() && seed < 0) {
            if (state_[pending_.front()] == Deferred) seed = pending_.front();
            pending_.pop_front();
        }
        while (seed < 0 && scan_ < int(state_.size())) {
            if (state_[scan_] == Unvisited) seed = scan_;
            ++scan_;
        }
        // [bfs-next]
        if (seed < 0) {
            pathActive_ = false;  // every ray of this path is traced
            continue;
        }
        ++regions_;
        state_[seed] = Queued;
        inflight_ = seed;
        inflightSeed_ = true;
        return Pick{tasks[slot_[seed]], LookupMode::Full};
    }
}

void BreadthFirstOrder::enqueueNeighbours(int local) {
    const int x = local % width_, y = local / width_;
    const int rows = nextRow_ - bandRow_;
    auto visit = [&](int nx, int ny) {
        if (nx < 0 || ny < 0 || nx >= width_ || ny >= rows) return;
        const int q = ny * width_ + nx;
        if (state_[q] == Unvisited || state_[q] == Deferred) {
            state_[q] = Queued;
            queue_.push_back(q);
        }
    };
    visit(x - 1, y);
    visit(x + 1, y);
    visit(x, y - 1);
    visit(x, y + 1);
    peak_ = std::max(peak_, queue_.size());
}

void BreadthFirstOrder::committed(const RayTask&, Decision d, std::vector<RayTask>& children) {
    for (RayTask& c : children) {
        if (c.node >= int(nextGeneration_.size())) nextGeneration_.resize(std::size_t(c.node) + 1);
        nextGeneration_[c.node].push_back(std::move(c));
    }
    state_[inflight_] = Done;
    // [bfs-extend]
    // A seed, or a ray the cache answered with the region's object, extends the region
    if (inflightSeed_ || d == Decision::Hit || d == Decision::Uncached) enqueueNeighbours(inflight_);
    // [bfs-extend]
}

void BreadthFirstOrder::deferred(const RayTask&) {
    state_[inflight_] = Deferred;
    pending_.push_back(inflight_);
}

FrontierView BreadthFirstOrder::frontier() const {
    FrontierView f;
    if (!pathActive_) return f;
    const int base = bandRow_ * width_;
    for (int q : queue_) f.queued.push_back(base + q);
    for (int q = 0; q < int(state_.size()); ++q)
        if (state_[q] == Deferred) f.deferred.push_back(base + q);
    f.path = generation_[pathIndex_].first;
    f.region = regions_;
    return f;
}

}  // namespace rc
