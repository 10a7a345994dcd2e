#include "view/miss_cause.h"

namespace rc {

// [miss-cause]
MissCause missCauseOf(const SessionState& s, const RayFocus& f) {
    MissCause c;
    if (f.decision != Decision::Miss || f.event < 0) return c;
    const auto& events = s.recorder().events();
    const int stop = std::max(0, f.event - kMissCauseReach);
    // The entry at this path was left by the last ray traced at it before this one
    for (int i = f.event - 1; i >= stop && c.cachedEvent < 0; --i) {
        const EventRecord& r = events[std::size_t(i)];
        if (!r.deferred() && r.node == f.node) c.cachedEvent = i;
    }
    if (c.cachedEvent < 0) return c;
    c.reason = f.reason;
    c.cachedObject = events[std::size_t(c.cachedEvent)].hit;
    if (f.reason == MissReason::BlockerHit) c.blocker = f.hit;
    // The cylinder (or cone) of the entry was built by the ray whose miss loaded it
    for (int i = c.cachedEvent; i >= stop && c.loadedEvent < 0; --i) {
        const EventRecord& r = events[std::size_t(i)];
        if (!r.deferred() && r.node == f.node && r.rayDecision() != Decision::Hit) c.loadedEvent = i;
    }
    if (f.reason == MissReason::LeftCylinder && c.loadedEvent >= 0)
        if (const auto loaded = RayFocus::ofEvent(s, c.loadedEvent)) c.cylinder = cylinderAround(s.scene(), *loaded);
    return c;
}
// [miss-cause]

}  // namespace rc
