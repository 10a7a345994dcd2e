#include "view/event_record.h"

#include <algorithm>
#include <cmath>

namespace rc {

namespace {
// Octahedral encoding of unit vectors (Cigolle et al. 2014): the sphere folded onto a square
float signOf(float v) { return v >= 0.0f ? 1.0f : -1.0f; }
std::int16_t quantise(float v) { return std::int16_t(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f)); }
}  // namespace

rc::Vec3 EventRecord::rayDirection() const {
    float x = d[0] / 32767.0f, y = d[1] / 32767.0f;
    const float z = 1.0f - std::abs(x) - std::abs(y);
    if (z < 0.0f) {
        const float fx = (1.0f - std::abs(y)) * signOf(x), fy = (1.0f - std::abs(x)) * signOf(y);
        x = fx;
        y = fy;
    }
    const rc::Vec3 v(x, y, z);
    return v / std::sqrt(double(x) * x + double(y) * y + double(z) * z);
}

void EventRecord::setRay(const rc::Ray& ray) {
    for (int k = 0; k < 3; ++k) o[k] = float(ray.o[k]);
    const rc::Vec3& v = ray.d;
    const double l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
    float x = float(v.x / l1), y = float(v.y / l1);
    if (v.z < 0.0) {
        const float fx = (1.0f - std::abs(y)) * signOf(x), fy = (1.0f - std::abs(x)) * signOf(y);
        x = fx;
        y = fy;
    }
    d[0] = quantise(x);
    d[1] = quantise(y);
}

void EventRecord::setDistance(bool known, const rc::Answer& a) {
    t = known && std::isfinite(a.t) ? float(a.t) : -1.0f;
}

EventRecord EventRecord::from(const rc::TraceEvent& e, int region, int previous) {
    EventRecord r;
    const rc::Query& q = e.task.query;
    r.step = std::int32_t(e.step);
    r.pixel = e.task.pixel;
    r.node = e.task.node;
    r.hit = e.lookup.known ? e.lookup.answer().object : -1;
    r.origin = q.origin.object;
    r.tests = e.tests;
    r.region = region;
    r.previous = previous;
    r.kind = std::uint8_t(q.kind);
    r.decision = std::uint8_t(e.lookup.decision);
    r.reason = std::uint8_t(e.lookup.reason);
    r.flags = std::uint8_t((e.deferred ? Deferred : 0) | (e.lookup.searched ? Searched : 0) |
                           (q.origin.inside ? Inside : 0));
    r.setRay(q.ray);
    if (e.lookup.known) r.setDistance(true, e.lookup.answer());
    else r.setDistance(false, {});
    return r;
}

}  // namespace rc

static_assert(sizeof(rc::EventRecord) == 56, "an event record is 56 bytes");
