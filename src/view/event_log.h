#pragma once
/// \file
/// \brief The recorder's log of every traced ray, kept as a byte stream rather than an
/// rc::EventRecord each: a render of a million pixels hears millions of events, and the
/// page (a browser tab) and the Qt GUI keep them all.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "view/block_vector.h"
#include "view/event_record.h"

namespace rc {

/// An append-only log of rc::EventRecord, encoded compactly and given back exactly: every
/// field reads as it was appended. Each event is coded against the one before it in its
/// group of kGroup events (its step and pixel as differences, its origin and region only
/// when they change, its small numbers in as few bytes as they need); a group starts from
/// nothing, so reading event i decodes at most kGroup events, and reading in order
/// (const_iterator) decodes each once.
class EventLog {
public:
    /// Events a group holds: what a random read decodes at most.
    static constexpr std::size_t kGroup = 64;

    /// Keep no ray from now on: each event reads back with o and d zero, and t -1; its ray
    /// and its hit distance are traced again when asked (rc::impliedRay,
    /// SessionState::event). Set while empty (a log keeps its rays or not from the start).
    void dropRays();
    /// Are the rays left out (dropRays())?
    bool raysDropped() const { return dropRays_; }

    void push_back(const EventRecord& r);
    /// Event `i` (< size()), decoded.
    EventRecord operator[](std::size_t i) const;
    EventRecord back() const { return (*this)[size_ - 1]; }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    /// Keeps the first `n` events (n <= size()), freeing the memory past them.
    void truncate(std::size_t n);
    /// Bytes allocated: the byte chunks and the index of groups.
    std::size_t bytes() const;

    /// Reads the events in order from one of them, decoding each once.
    class const_iterator {
    public:
        const_iterator(const EventLog* log, std::size_t i);
        EventRecord operator*() const { return current_; }
        const_iterator& operator++();
        bool operator!=(const const_iterator& o) const { return i_ != o.i_; }
        bool operator==(const const_iterator& o) const { return i_ == o.i_; }
        std::size_t index() const { return i_; }

    private:
        const EventLog* log_;
        std::size_t i_;
        std::uint64_t pos_ = 0;  ///< where the event after current_ starts
        EventRecord current_;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size_}; }
    /// An iterator at event `i` (<= size()).
    const_iterator from(std::size_t i) const { return {this, i}; }
    /// Calls `f(index, event)` for the events before `end`, newest first, until it returns
    /// true; returns the index it stopped at, -1 if none. Decodes each event once.
    template <class F>
    std::int64_t findBackward(std::size_t end, F&& f) const {
        EventRecord group[kGroup];
        for (std::size_t g = (std::min(end, size_) + kGroup - 1) / kGroup; g-- > 0;) {
            const std::size_t n = decodeGroup(g, group);
            for (std::size_t k = n; k-- > 0;)
                if (g * kGroup + k < end && f(g * kGroup + k, group[k])) return std::int64_t(g * kGroup + k);
        }
        return -1;
    }

private:
    /// Bytes a chunk holds: an event is never split between two. Small enough that the
    /// last chunk's unused end is nothing beside a render's log (about 5 bytes an event).
    static constexpr std::size_t kChunk = std::size_t(1) << 16;
    /// The most bytes one event takes.
    static constexpr std::size_t kMaxEvent = 96;

    /// Decodes event `index`, which starts at `pos` and is coded against `before` (a
    /// default EventRecord for the first of a group), into `out`; returns where it ends.
    std::uint64_t decode(std::uint64_t pos, std::size_t index, const EventRecord& before, EventRecord& out) const;
    /// Decodes group `g` into `out`; returns how many events it holds.
    std::size_t decodeGroup(std::size_t g, EventRecord* out) const;
    /// Where the event at `pos` really starts: past the unused end of a chunk.
    std::uint64_t skipEnd(std::uint64_t pos) const;

    std::vector<std::unique_ptr<std::uint8_t[]>> chunks_;
    std::vector<std::uint32_t> used_;  ///< bytes used in each chunk
    BlockVector<std::uint64_t, 4096> groups_;  ///< where each group starts (chunk * kChunk + offset)
    std::size_t size_ = 0;
    EventRecord last_;  ///< what the next event is coded against: the last one appended, unless it starts a group
    bool dropRays_ = false;
};

}  // namespace rc
