/// \file
/// \brief The seed fill of rc::BreadthFirstOrder: which ray comes next (next()), how a region
/// grows (committed(), enqueueNeighbours()) and what waits (deferred()). Tutorial 04's hole: a
/// student build compiles tutorials/04-breadth-first-fill/exercise.cpp in place of this file.
/// The band, path and grid bookkeeping (beginPath()) is in order/breadth_first_order.cpp.
#include <algorithm>
#include <cstring>

#include "geometry/student_code.h"
#include "order/breadth_first_order.h"

namespace rc {

std::optional<Pick> BreadthFirstOrder::next() {
    for (;;) {
        if (!pathActive_ && !beginPath()) return std::nullopt;
        const std::vector<RayTask>& tasks = paths_[generation_[pathIndex_]];
        if (walks_) {
            if (auto pick = walk(tasks)) return pick;
            pathActive_ = false;
            continue;
        }
        // BEGIN SOLUTION 04
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
        // END SOLUTION
        // BEGIN STUB
        // // TODO 2: while the region's queue (queue_) holds pixels, take the first and ask
        // // its ray with the cheap test only (LookupMode::CheapOnly when cheapTests_). Only
        // // when the region is finished does a new one start: a deferred pixel still waiting
        // // (pending_, state_ Deferred), else the next untouched one (nextUnvisited()).
        // notYet(4);
        // int seed = nextUnvisited();  // every ray a seed: a complete search each
        // END STUB
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
    // BEGIN SOLUTION 04
    // [bfs-grow]
    // What trying a pixel makes of its state: untouched, or deferred by an earlier region,
    // this region queues it; any other state stays
    static constexpr State kTried[] = {Absent, Queued, Queued, Queued, Done};
    // Whether a neighbour is taken is a coin toss the processor would guess wrong half the
    // time: each is written at the queue's end, which moves past it only if it was taken
    // (room for four is made, and what was not taken is dropped again below)
    const std::size_t before = queue_.items.size();
    queue_.items.resize(before + 4);
    int* const queued = queue_.items.data();
    std::size_t end = before;
    auto visit = [&](int q) {
        const State was = state[q];
        const bool tries = was == Unvisited || was == Deferred;
        state[q] = kTried[was];
        queued[end] = q;
        end += tries;
        // Its ray is traced soon: start fetching it now (if not taken, the path's first: harmless)
        const char* task = reinterpret_cast<const char*>(tasks + (slot[q] & -int(tries)));
        for (std::size_t line = 0; line < sizeof(RayTask); line += 64) __builtin_prefetch(task + line);
    };
    // The 4-neighbours inside the band
    if (x > 0) visit(local - 1);
    if (x + 1 < width_) visit(local + 1);
    if (y > 0) visit(local - width_);
    if (y + 1 < rows) visit(local + width_);
    queue_.items.resize(end);
    // [bfs-grow]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 1: queue the neighbours of pixel (x, y) that this region should try next
    // // (queue_, and state_ Queued), within the band's `rows` and the image's width_.
    // (void)x, (void)rows, (void)state, (void)slot, (void)tasks;
    // END STUB
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

}  // namespace rc
