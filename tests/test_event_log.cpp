// The recorder's event log gives back every event exactly as it was appended, in fewer bytes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <tuple>
#include <vector>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "view/event_log.h"

namespace {

bool same(const rc::EventRecord& a, const rc::EventRecord& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every event of a render as the recorder makes it (rc::EventRecord::from), kept plainly
struct Plain final : rc::TraceSink {
    const rc::RayOrder* order = nullptr;
    std::vector<rc::EventRecord> events;
    std::vector<int> last;
    void onEvent(const rc::TraceEvent& e) override {
        if (last.size() <= std::size_t(e.task.pixel)) last.resize(std::size_t(e.task.pixel) + 1, -1);
        events.push_back(rc::EventRecord::from(e, int(order->regions()), last[std::size_t(e.task.pixel)]));
        last[std::size_t(e.task.pixel)] = int(events.size()) - 1;
    }
};

std::vector<rc::EventRecord> renderEvents(const char* scene, rc::CacheKind cache, rc::OrderKind order, int size) {
    rc::RenderOptions o;
    o.cache = cache;
    o.order = order;
    o.width = o.height = size;
    rc::RenderSession s(std::make_shared<const rc::Scene>(rc::loadScene(scene)), o);
    Plain plain;
    plain.order = &s.order();
    s.addSink(&plain);
    while (s.step()) {
    }
    return plain.events;
}

// The log holds `events`: read one by one, in order from every start, and newest first
void requireHolds(const rc::EventLog& log, const std::vector<rc::EventRecord>& events) {
    REQUIRE(log.size() == events.size());
    std::size_t i = 0;
    for (const rc::EventRecord& r : log) REQUIRE(same(r, events[i++]));
    for (std::size_t k = 0; k < events.size(); k += 7) {
        REQUIRE(same(log[k], events[k]));
        auto it = log.from(k);
        for (std::size_t j = k; j < std::min(events.size(), k + 40); ++j, ++it) REQUIRE(same(*it, events[j]));
    }
    std::size_t back = events.size();
    log.findBackward(events.size(), [&](std::size_t at, const rc::EventRecord& r) {
        REQUIRE(at == --back);
        REQUIRE(same(r, events[at]));
        return false;
    });
    REQUIRE(back == 0);
}

}  // namespace

TEST_CASE("The event log gives back a render's events exactly, in under half their bytes", "[view]") {
    for (const auto& [scene, cache, order] :
         {std::tuple{"cube:3", rc::CacheKind::BlockerPlus, rc::OrderKind::BreadthFirst},
          std::tuple{"balls:2", rc::CacheKind::Cylinder, rc::OrderKind::Scanline},
          std::tuple{"trio", rc::CacheKind::Blocker, rc::OrderKind::BreadthFirst}}) {
        CAPTURE(scene);
        const std::vector<rc::EventRecord> events = renderEvents(scene, cache, order, 48);
        REQUIRE(events.size() > 2304);
        rc::EventLog log;
        for (const rc::EventRecord& r : events) log.push_back(r);
        requireHolds(log, events);
        // 56 bytes an event as records; the log's last chunk (EventLog's kChunk, 64 KiB) may
        // be mostly unused
        const double perEvent = double(log.bytes() - (std::size_t(1) << 16)) / double(events.size());
        CAPTURE(perEvent);
        REQUIRE(perEvent < 28.0);
    }
}

TEST_CASE("The event log, cut back, takes events again as if never cut", "[view]") {
    const std::vector<rc::EventRecord> events =
        renderEvents("cube:3", rc::CacheKind::BlockerPlus, rc::OrderKind::BreadthFirst, 64);
    rc::EventLog log;
    for (const rc::EventRecord& r : events) log.push_back(r);
    // Inside a group, at a group's start, at nothing; then the same events appended again
    for (const std::size_t n : {events.size() - 1, events.size() / 2 + 5, std::size_t(rc::EventLog::kGroup * 100),
                                std::size_t(3), std::size_t(0)}) {
        CAPTURE(n);
        log.truncate(n);
        REQUIRE(log.size() == n);
        for (std::size_t i = n; i < events.size(); ++i) log.push_back(events[i]);
        requireHolds(log, events);
    }
}

TEST_CASE("The event log keeps odd values as they are: none, negative, huge, NaN, raw header", "[view]") {
    std::vector<rc::EventRecord> events;
    rc::EventRecord r;
    events.push_back(r);  // as default-made
    r.step = std::numeric_limits<std::int32_t>::max();
    r.pixel = std::numeric_limits<std::int32_t>::min();
    r.node = -7;
    r.hit = std::numeric_limits<std::int32_t>::max();
    r.origin = -2;
    r.tests = -1;
    r.region = std::numeric_limits<std::int32_t>::min();
    r.previous = 5;  // not before it: kept as it is
    r.kind = 200;    // outside the narrow header
    r.flags = 255;
    r.t = std::numeric_limits<float>::quiet_NaN();
    r.o[1] = -0.0f;
    r.d[0] = -32768;
    events.push_back(r);
    r.step = std::numeric_limits<std::int32_t>::min();
    r.previous = 0;
    r.kind = 1;
    r.flags = 2;
    r.t = -0.0f;
    events.push_back(r);
    r.previous = -5;
    r.t = std::numeric_limits<float>::infinity();
    events.push_back(r);
    rc::EventLog log;
    for (const rc::EventRecord& e : events) log.push_back(e);
    requireHolds(log, events);
}
