#include "view/trace_recorder.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

TraceRecorder::TraceRecorder(int width, int height, const rc::RayOrder* order)
    : width_(width), height_(height), order_(order) {
    const std::size_t n = std::size_t(width) * height;
    lastOfPixel_.assign(n, -1);
    tests_.assign(n, 0);
    hits_.assign(n, 0);
    missCount_.assign(n, 0);
    firstVisit_.assign(n, -1);
    missReason_.assign(n, 0);
}

void TraceRecorder::dropTallies() {
    if (!events_.empty()) throw std::logic_error("TraceRecorder::dropTallies: events were recorded");
    const std::size_t n = std::size_t(width_) * height_;
    for (auto* v : {&hits_, &missCount_}) std::vector<std::uint32_t>().swap(*v);
    std::vector<std::int32_t>().swap(firstVisit_);
    std::vector<std::uint8_t>().swap(missReason_);
    std::vector<std::int32_t>().swap(tests_);
    visited_.assign(n, false);
    talliesDropped_ = true;
}

void TraceRecorder::onEvent(const rc::TraceEvent& e) {
    const int p = e.task.pixel;
    const int region = order_ ? int(order_->regions()) : 0;
    events_.push_back(EventRecord::from(e, region, lastOfPixel_[p]));
    const int index = int(events_.size()) - 1;
    lastOfPixel_[p] = index;
    last_ = e;
    if (talliesDropped_) {
        if (!e.deferred) {
            lastCommitted_ = e;
            visited_[std::size_t(p)] = true;
        }
        return;
    }
    tests_[p] += e.tests;
    testsRead_ = events_.size();
    if (e.deferred) {
        misses_.push_back(index);
        return;
    }
    lastCommitted_ = e;
    if (firstVisit_[p] < 0) firstVisit_[p] = std::int32_t(e.step);
    if (e.lookup.decision == rc::Decision::Hit) ++hits_[p];
    if (e.lookup.decision == rc::Decision::Miss) {
        misses_.push_back(index);
        ++missCount_[p];
        if (missReason_[p] == 0) missReason_[p] = std::uint8_t(e.lookup.reason);
    }
}

std::size_t TraceRecorder::pixelBytes() const {
    const auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(lastOfPixel_) + bytes(tests_) + bytes(hits_) + bytes(missCount_) + bytes(firstVisit_) +
           bytes(missReason_) + (visited_.capacity() + 7) / 8;
}

void TraceRecorder::readTests() const {
    if (tests_.empty()) tests_.assign(std::size_t(width_) * height_, 0);
    for (auto it = events_.from(testsRead_); it != events_.end(); ++it) {
        const EventRecord r = *it;
        tests_[std::size_t(r.pixel)] += r.tests;
    }
    testsRead_ = events_.size();
}

std::vector<int> TraceRecorder::eventsOf(int pixel) const {
    std::vector<int> out;
    for (int i = lastOfPixel_[pixel]; i >= 0; i = events_[std::size_t(i)].previous) out.push_back(i);
    std::reverse(out.begin(), out.end());
    return out;
}

int TraceRecorder::eventAt(int pixel, int node) const {
    for (int i = lastOfPixel_[pixel]; i >= 0;) {
        const EventRecord r = events_[std::size_t(i)];
        if (r.node == node && !r.deferred()) return i;
        i = r.previous;
    }
    return -1;
}

void TraceRecorder::sample(const StatSample& s) {
    if (!samples_.empty() && s.step - samples_.back().step < sampleEvery_) return;
    samples_.push_back(s);
    if (samples_.size() >= 2000) {
        // Keep every other sample and sample half as often from now on
        std::vector<StatSample> kept;
        for (std::size_t i = 0; i < samples_.size(); i += 2) kept.push_back(samples_[i]);
        samples_.swap(kept);
        sampleEvery_ *= 2;
    }
}

TraceRecorder::Mark TraceRecorder::mark() const {
    return {events_.size(), misses_.size(), last_, lastCommitted_, samples_, sampleEvery_};
}

void TraceRecorder::rollback(const Mark& m) {
    if (m.events > events_.size() || m.misses > misses_.size())
        throw std::invalid_argument("TraceRecorder::rollback: a mark of another recorder");
    // Take each event back, newest first: what onEvent() added, it subtracts
    std::vector<int> unvisited;  // with the tallies dropped: pixels that lost a committed event
    events_.findBackward(events_.size(), [&](std::size_t i, const EventRecord& r) {
        if (i < m.events) return true;
        const int p = r.pixel;
        lastOfPixel_[p] = r.previous;
        if (i < testsRead_) tests_[p] -= r.tests;  // counted (tallies dropped: if read)
        if (r.deferred()) return false;
        if (talliesDropped_) {
            if (visited_[std::size_t(p)]) unvisited.push_back(p);
            visited_[std::size_t(p)] = false;
            return false;
        }
        if (firstVisit_[p] == r.step) firstVisit_[p] = -1;
        if (r.rayDecision() == rc::Decision::Hit) --hits_[p];
        // The first miss goes last: with it goes the pixel's miss reason
        if (r.rayDecision() == rc::Decision::Miss && --missCount_[p] == 0) missReason_[p] = 0;
        return false;
    });
    events_.truncate(m.events);
    misses_.truncate(m.misses);
    testsRead_ = std::min(testsRead_, m.events);
    // A pixel is still visited when a committed event of it is left
    for (const int p : unvisited)
        for (int i = lastOfPixel_[p]; i >= 0 && !visited_[std::size_t(p)];) {
            const EventRecord r = events_[std::size_t(i)];
            visited_[std::size_t(p)] = !r.deferred();
            i = r.previous;
        }
    last_ = m.last;
    lastCommitted_ = m.lastCommitted;
    samples_ = m.samples;
    sampleEvery_ = m.sampleEvery;
}

}  // namespace rc
