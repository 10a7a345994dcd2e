#include "view/path_index.h"

#include <algorithm>

namespace rc {

PathIndex::Update PathIndex::update(const TraceRecorder& rec, std::uint64_t serial, int node, std::size_t budget) {
    Update u;
    const std::size_t pixels = std::size_t(rec.width()) * std::size_t(rec.height());
    const auto& events = rec.events();
    // Start over for another state, another path, or a log taken back
    if (serial != serial_ || node != node_ || events.size() < read_ || at_.size() != pixels) {
        at_.assign(pixels, Entry{});
        serial_ = serial;
        node_ = node;
        read_ = 0;
        u.rebuilt = true;
    }
    // Read the new events in order: the newest committed one at the path wins
    const std::size_t end = budget == 0 ? events.size() : std::min(events.size(), read_ + budget);
    for (auto it = events.from(read_); it.index() < end; ++it) {
        const std::size_t i = it.index();
        const EventRecord e = *it;
        if (e.node != node || e.deferred()) continue;
        at_[std::size_t(e.pixel)] = {std::int32_t(i), e.region, e.decision, e.reason};
        if (!u.rebuilt) u.pixels.push_back(e.pixel);
    }
    read_ = end;
    u.complete = end == events.size();
    return u;
}

}  // namespace rc
