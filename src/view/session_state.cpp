#include "view/session_state.h"

#include <algorithm>
#include <chrono>

#include "view/implied_ray.h"

namespace rc {

namespace {
std::unique_ptr<rc::RenderSession> makeSession(const SessionConfig& c) {
    return std::make_unique<rc::RenderSession>(c.scene, c.options);
}
}  // namespace

namespace {
std::atomic<std::uint64_t> nextSerial{1};
}  // namespace

SessionState::SessionState(SessionConfig config)
    : serial_(nextSerial++),
      config_(std::move(config)),
      session_(makeSession(config_)),
      camera_(config_.scene->camera, session_->width(), session_->height()),
      recorder_(session_->width(), session_->height(), &session_->order()),
      checkpoints_(config_.checkpointEvery) {
    if (!config_.keepRays && raysImplied(*session_)) recorder_.dropRays();
    if (!config_.keepTallies) recorder_.dropTallies();
    session_->addSink(&recorder_);
    sample();
    checkpoint();
}

SessionState::~SessionState() {
    session_->removeSink(&recorder_);
}

const SampleFan& SessionState::fan(int pixel) const {
    if (!fan_ || fan_->pixel != pixel) fan_ = std::make_unique<SampleFan>(SampleFan::trace(*session_, pixel));
    return *fan_;
}

EventRecord SessionState::event(std::size_t i) const {
    EventRecord r = recorder_.events()[i];
    if (recorder_.events().raysDropped())
        if (const auto ray = impliedRay(*session_, r.pixel, r.node)) {
            const rc::Query& q = ray->task.query;
            r.setRay(q.ray);
            // Every ray's answer is its nearest hit but a shadow ray's: a cache may answer
            // one with any object in the way, the object the event keeps, at its distance
            // along the ray
            if (r.rayKind() != rc::RayKind::Shadow) r.setDistance(!r.deferred(), ray->nearest);
            else if (r.hit >= 0) r.setDistance(true, {r.hit, scene().intersect(q.ray, r.hit, q.origin)});
        }
    return r;
}

const rc::BeamTreeBuilder& SessionState::beams() const {
    const EventLog& events = recorder_.events();
    // A new serial (Step back) or a log cut back: start over
    if (!beams_ || beamsSerial_ != serial_ || beamsRead_ > events.size()) {
        beams_ = std::make_unique<rc::BeamTreeBuilder>(width(), height());
        beamsRead_ = 0;
        beamsSerial_ = serial_;
    }
    // Committed rays only, as rc::BeamTreeBuilder::onEvent takes them from the render
    for (auto it = events.from(beamsRead_); it != events.end(); ++it) {
        const EventRecord r = *it;
        if (!r.deferred()) beams_->record(r.node, r.pixel, r.origin, r.flags & EventRecord::Inside, r.hit);
    }
    beamsRead_ = events.size();
    return *beams_;
}

void SessionState::sample() {
    const rc::Counters& n = session_->counters();
    recorder_.sample({session_->steps(), n.hits, n.misses, n.intersectionTests});
}

void SessionState::checkpoint() {
    // Into the memory of one dropped, if any: fresh memory is what a checkpoint costs most
    StepCheckpoint c = checkpoints_.spare();
    const StepCheckpoint* last = checkpoints_.last();
    session_->checkpointInto(c.session, last ? &last->session : nullptr);
    c.recorder = recorder_.mark();
    checkpoints_.add(std::move(c));
}

std::int64_t SessionState::rewindTo(std::int64_t step) {
    // [rewind]
    // The latest checkpoint at or before the step: the render and its recorder go back
    // to it; what is left is replayed by stepping
    if (step < 0 || step >= session_->steps()) return 0;
    const StepCheckpoint* c = checkpoints_.backTo(step);
    if (!c) return 0;  // never: step 0 always has one
    session_->restore(c->session);
    recorder_.rollback(c->recorder);
    // [rewind]
    stopEvent_ = -1;
    fan_.reset();
    serial_ = nextSerial++;
    return step - c->steps();
}

bool SessionState::step() {
    const bool more = session_->step();
    if (more) {
        sample();
        if (checkpoints_.due(session_->steps())) checkpoint();
    }
    return more;
}

bool SessionState::runUntil(RunGoal goal, std::int64_t target, const std::atomic<bool>* cancel,
                            const std::function<void()>& tick) {
    using Clock = std::chrono::steady_clock;
    auto nextTick = Clock::now() + std::chrono::milliseconds(50);
    const int startPixel = recorder_.lastCommitted() ? recorder_.lastCommitted()->task.pixel : -1;
    std::size_t eventsBefore = recorder_.events().size();
    stopEvent_ = -1;
    for (std::int64_t n = 0;; ++n) {
        if (goal == RunGoal::ToStep && session_->steps() >= target) return true;
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        if (!step()) return true;
        const auto& events = recorder_.events();
        if (goal == RunGoal::NextMiss || goal == RunGoal::NextDeferral) {
            for (auto it = events.from(eventsBefore); it != events.end(); ++it) {
                const EventRecord e = *it;
                const bool met = goal == RunGoal::NextDeferral
                                     ? e.deferred()
                                     : !e.deferred() && e.rayDecision() == rc::Decision::Miss &&
                                           (missFilter_ == rc::MissReason::None || e.missReason() == missFilter_);
                if (met) {
                    stopEvent_ = int(it.index());
                    return true;
                }
            }
            eventsBefore = events.size();
        }
        if (goal == RunGoal::NextPixel && recorder_.lastCommitted()->task.pixel != startPixel)
            return true;
        if (tick && (n & 255) == 0 && Clock::now() >= nextTick) {
            tick();
            nextTick = Clock::now() + std::chrono::milliseconds(50);
        }
    }
}

}  // namespace rc
