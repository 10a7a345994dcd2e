#pragma once
/// \file
/// \brief A trace sink that keeps every event and per-pixel tallies for the GUI.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include "view/block_vector.h"
#include "view/event_log.h"
#include "order/ray_order.h"

namespace rc {

/// Counters sampled over time, for the statistics chart.
struct StatSample {
    std::int64_t step = 0;
    std::uint64_t hits = 0;
    std::uint64_t misses = 0;
    std::uint64_t tests = 0;
};

/// Records every trace event of a session (compactly), the last full event, and per
/// pixel: tests made, hits, misses, the step it was first visited and its last miss.
class TraceRecorder final : public rc::TraceSink {
public:
    /// `order` is read for the breadth-first region of each event; it may be null.
    TraceRecorder(int width, int height, const rc::RayOrder* order);
    void onEvent(const rc::TraceEvent& e) override;

    int width() const { return width_; }
    int height() const { return height_; }
    const EventLog& events() const { return events_; }
    /// Keep no event's ray (EventLog::dropRays); before the first event.
    void dropRays() { events_.dropRays(); }
    /// Keep only the tallies the page reads (whether a pixel was visited, and its tests once
    /// asked: testsAt()), not hits, misses, first visits and miss reasons (a bit a pixel, 4
    /// bytes more with the tests, not 17), nor the index of misses (the Qt GUI's event log
    /// panel reads it). Before the first event;
    /// misses(), hitsAt(), missesAt(), firstVisit() and missReasonAt() then throw.
    void dropTallies();
    /// Are they left out (dropTallies())?
    bool talliesDropped() const { return talliesDropped_; }
    /// Indices into events() of committed misses and of deferrals, in order.
    const BlockVector<std::int32_t>& misses() const { return kept(misses_); }
    /// Bytes the per-event record takes (events and the miss index), to weigh against
    /// events().size(). The per-pixel tallies come on top: pixelBytes().
    std::size_t eventBytes() const { return events_.bytes() + misses_.bytes(); }
    /// Bytes the per-pixel tallies take, counted from what is allocated.
    std::size_t pixelBytes() const;
    /// The last event heard (committed or deferred), if any.
    const std::optional<rc::TraceEvent>& lastEvent() const { return last_; }
    /// The last committed event, if any.
    const std::optional<rc::TraceEvent>& lastCommitted() const { return lastCommitted_; }
    /// Index of the pixel's newest event, -1 if none; follow EventRecord::previous.
    int lastEventOf(int pixel) const { return lastOfPixel_[pixel]; }
    /// Every event of a pixel, oldest first.
    std::vector<int> eventsOf(int pixel) const;
    /// The committed event of `pixel` at path `node`, or -1.
    int eventAt(int pixel, int node) const;

    /// Ray-object tests of every ray of the pixel. With the tallies dropped they are counted
    /// from the log when first asked (the page's tests heatmap), and from then on kept up
    /// with it: a page that never shows the heatmap holds no tally of its tests.
    std::int32_t testsAt(int pixel) const {
        if (testsRead_ != events_.size()) readTests();
        return tests_[std::size_t(pixel)];
    }
    /// Committed cache hits and misses of every ray of the pixel (all samples): a pixel of
    /// 256 samples with 64 shadow rays each makes more lookups than 16 bits hold.
    std::uint32_t hitsAt(int pixel) const { return kept(hits_)[std::size_t(pixel)]; }
    std::uint32_t missesAt(int pixel) const { return kept(missCount_)[std::size_t(pixel)]; }
    /// Step at which the pixel's first committed ray was traced, -1 if none.
    std::int32_t firstVisit(int pixel) const { return kept(firstVisit_)[std::size_t(pixel)]; }
    /// Has a committed ray of the pixel been traced? (firstVisit() >= 0; kept when the
    /// tallies are dropped too.)
    bool visited(int pixel) const {
        return talliesDropped_ ? visited_[std::size_t(pixel)] : firstVisit_[std::size_t(pixel)] >= 0;
    }
    /// Reason of the pixel's first committed miss (rc::MissReason::None if none).
    rc::MissReason missReasonAt(int pixel) const { return rc::MissReason(kept(missReason_)[std::size_t(pixel)]); }

    /// Adds a chart sample; keeps at most about 2000 by thinning old ones.
    void sample(const StatSample& s);
    const std::vector<StatSample>& samples() const { return samples_; }

    /// The recorder at a checkpoint: events are a log that only grows, so it keeps their
    /// count (and what is not a log: the last events and the chart samples).
    struct Mark {
        std::size_t events = 0, misses = 0;
        std::optional<rc::TraceEvent> last, lastCommitted;
        std::vector<StatSample> samples;
        std::int64_t sampleEvery = 1;
        std::size_t bytes() const { return sizeof(Mark) + samples.size() * sizeof(StatSample); }
    };
    Mark mark() const;
    /// Forgets the events recorded after `m` (a mark of this recorder, taken before them):
    /// the per-pixel tallies are taken back event by event, newest first.
    void rollback(const Mark& m);

private:
    /// A tally dropTallies() may have left out: throws when it was.
    template <class V>
    const V& kept(const V& tally) const {
        if (talliesDropped_) throw std::logic_error("TraceRecorder: this tally is not kept (dropTallies)");
        return tally;
    }

    int width_, height_;
    const rc::RayOrder* order_;
    EventLog events_;
    BlockVector<std::int32_t> misses_;
    /// Counts the tests of the events from testsRead_ on into tests_ (with the tallies
    /// dropped; kept, onEvent() counts them)
    void readTests() const;

    std::vector<std::int32_t> lastOfPixel_;
    /// Tests by pixel, of the first testsRead_ events (empty until read, tallies dropped)
    mutable std::vector<std::int32_t> tests_;
    mutable std::size_t testsRead_ = 0;
    std::vector<std::uint32_t> hits_, missCount_;
    /// A step fits 32 bits as an event's index does: a step is counted in committed
    /// events, and the log numbers its events in 32 bits (EventRecord::step, lastOfPixel_).
    std::vector<std::int32_t> firstVisit_;
    std::vector<std::uint8_t> missReason_;
    /// With the tallies dropped, whether a pixel was visited (in place of firstVisit_)
    std::vector<bool> visited_;
    bool talliesDropped_ = false;
    std::optional<rc::TraceEvent> last_, lastCommitted_;
    std::vector<StatSample> samples_;
    std::int64_t sampleEvery_ = 1;
};

}  // namespace rc
