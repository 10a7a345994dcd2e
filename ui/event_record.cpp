#include "event_record.h"

#include <cmath>

namespace rcgui {

EventRecord EventRecord::from(const rc::TraceEvent& e, int region, int previous) {
    EventRecord r;
    const rc::Query& q = e.task.query;
    r.step = e.step;
    r.pixel = e.task.pixel;
    r.node = e.task.node;
    r.hit = e.lookup.known ? e.lookup.answer.object : -1;
    r.origin = q.origin.object;
    r.tests = e.tests;
    r.region = region;
    r.previous = previous;
    r.kind = std::uint8_t(q.kind);
    r.decision = std::uint8_t(e.lookup.decision);
    r.reason = std::uint8_t(e.lookup.reason);
    r.flags = std::uint8_t((e.deferred ? Deferred : 0) | (e.lookup.searched ? Searched : 0) |
                           (q.origin.inside ? Inside : 0));
    for (int k = 0; k < 3; ++k) {
        r.o[k] = float(q.ray.o[k]);
        r.d[k] = float(q.ray.d[k]);
    }
    r.t = e.lookup.known && std::isfinite(e.lookup.answer.t) ? float(e.lookup.answer.t) : -1.0f;
    r.tmax = std::isfinite(q.tmax) ? float(q.tmax) : -1.0f;
    return r;
}

}  // namespace rcgui
