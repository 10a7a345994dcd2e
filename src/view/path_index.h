#pragma once
/// \file
/// \brief Each pixel's committed event at one path of the ray tree, kept up to date as
/// events arrive, so that a per-pixel layer costs one read of each new event.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "view/trace_recorder.h"

namespace rc {

/// For one ray-tree path (eye, eye/reflection, ...): the newest committed event of every
/// pixel there, as TraceRecorder::eventAt() gives it, for all pixels at once, with what
/// the per-pixel layers draw copied beside it. Events are a log that only grows while a
/// state keeps its serial, so an update reads only the events added since the last one;
/// a budget splits a long log over several updates.
class PathIndex {
public:
    /// What the index keeps of a pixel's event.
    struct Entry {
        std::int32_t event = -1;  ///< index in TraceRecorder::events(), -1 for none
        std::int32_t region = 0;  ///< its breadth-first region
        std::uint8_t decision = 0;  ///< rc::Decision
        std::uint8_t reason = 0;    ///< rc::MissReason
    };

    /// What an update changed.
    struct Update {
        bool rebuilt = false;     ///< started over: every pixel may have changed
        bool complete = true;     ///< every event of the recorder has been read
        std::vector<int> pixels;  ///< when not rebuilt: the pixels whose event changed
    };

    /// Brings the index up to `rec` at path `node`, reading at most `budget` events (0:
    /// all). `serial` names the state the events belong to (rc::SessionState::serial()):
    /// a new serial, another path, or a log that shrank starts over.
    Update update(const TraceRecorder& rec, std::uint64_t serial, int node, std::size_t budget = 0);

    const Entry& at(int pixel) const { return at_[std::size_t(pixel)]; }
    /// The committed event of `pixel` at the path, or -1.
    int eventAt(int pixel) const { return at(pixel).event; }
    int node() const { return node_; }
    /// Pixels the index covers (width x height of the recorder).
    std::size_t pixels() const { return at_.size(); }
    /// Events read so far.
    std::size_t read() const { return read_; }

private:
    std::uint64_t serial_ = 0;
    int node_ = -1;
    std::size_t read_ = 0;
    std::vector<Entry> at_;
};

}  // namespace rc
