#pragma once
/// \file
/// \brief One render as the GUI sees it: the session, its recorder and its beam tree.
#include <atomic>
#include <functional>
#include <memory>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "view/sample_fan.h"
#include "scene/camera.h"
#include "view/step_checkpoints.h"
#include "view/trace_recorder.h"

namespace rc {

/// What a render is made of: the scene and the options (cache, order, size).
struct SessionConfig {
    std::shared_ptr<const rc::Scene> scene;
    rc::RenderOptions options;
    /// Steps between checkpoints (StepCheckpoints), which Step back goes back to.
    std::int64_t checkpointEvery = StepCheckpoints::kEvery;
    /// Keep every event's ray in the recorder's log. Otherwise (the default) the log keeps
    /// none when they can be traced again exactly (rc::raysImplied), and event() traces
    /// an event's ray again when asked.
    bool keepRays = false;
    /// Keep every per-pixel tally (hits, misses, first visits, miss reasons: the Qt GUI's
    /// heatmaps and tooltips) and the index of misses (its event log panel). Otherwise only
    /// tests and whether a pixel was visited, as the page reads (TraceRecorder::dropTallies).
    bool keepTallies = true;
};

/// How far a multi-step run goes.
enum class RunGoal {
    ToEnd,      ///< until the image is complete
    ToStep,     ///< until session().steps() reaches a target
    NextMiss,   ///< until a committed cache miss (stopEvent() is the miss)
    NextDeferral, ///< until a ray is deferred: its cheap test failed (stopEvent() is the deferral)
    NextPixel,  ///< until a ray of another pixel than the last one is traced
};

/// A render session with the sinks the GUI needs. Not thread-safe: exactly one thread
/// may use it at a time (SessionController hands it to its worker and back).
class SessionState {
public:
    explicit SessionState(SessionConfig config);
    ~SessionState();
    SessionState(const SessionState&) = delete;
    SessionState& operator=(const SessionState&) = delete;

    /// Traces exactly one ray (see rc::RenderSession::step). False when the image is done.
    bool step();
    /// Steps towards `goal` (`target` is the step count for RunGoal::ToStep) until it is
    /// met, the image is done, or `cancel` becomes true. `tick` is called now and then
    /// (about every 1/20 s). Returns true when the goal was met or the image completed.
    bool runUntil(RunGoal goal, std::int64_t target, const std::atomic<bool>* cancel = nullptr,
                  const std::function<void()>& tick = {});

    /// Goes back to the latest checkpoint at or before `step` (< steps()): the render, its
    /// recorder and its beams as they were there. Returns the steps left to replay to
    /// reach `step` (fewer than checkpoints().every()); the state takes a new serial().
    std::int64_t rewindTo(std::int64_t step);
    const StepCheckpoints& checkpoints() const { return checkpoints_; }
    std::string checkpointSummary() const { return checkpoints_.summary(); }

    /// The recorded event that met the last run's NextMiss/NextDeferral goal, else -1.
    int stopEvent() const { return stopEvent_; }
    /// Next miss stops only at misses of this reason (rc::MissReason::None: at any miss).
    void setMissFilter(rc::MissReason r) { missFilter_ = r; }
    rc::MissReason missFilter() const { return missFilter_; }

    const SessionConfig& config() const { return config_; }
    const rc::Scene& scene() const { return *config_.scene; }
    const rc::RenderSession& session() const { return *session_; }
    const TraceRecorder& recorder() const { return recorder_; }
    /// Recorded event `i` (< recorder().events().size()) with its ray: the log's, or, when
    /// the log keeps none, its pixel's ray at its path traced again (rc::impliedRay).
    EventRecord event(std::size_t i) const;
    /// The beam tree's builder, fed from the recorder's events when asked (only the events
    /// added since the last ask): a page that never asks keeps no second copy of its rays.
    const rc::BeamTreeBuilder& beams() const;
    /// The session's camera, to project world points to fractional pixel positions.
    const rc::RayGenerator& camera() const { return camera_; }
    int width() const { return session_->width(); }
    int height() const { return session_->height(); }
    /// A number no other SessionState of this process has: caches of derived pictures
    /// key on it (an address may be reused by the next state, e.g. after Step back).
    std::uint64_t serial() const { return serial_; }
    /// The sample rays of `pixel` (SampleFan::trace), kept for the last pixel asked: the
    /// overlays and the scene view ask on every paint.
    const SampleFan& fan(int pixel) const;

private:
    std::uint64_t serial_;
    int stopEvent_ = -1;
    rc::MissReason missFilter_ = rc::MissReason::None;
    void sample();
    void checkpoint();
    SessionConfig config_;
    std::unique_ptr<rc::RenderSession> session_;
    rc::RayGenerator camera_;
    TraceRecorder recorder_;
    mutable std::unique_ptr<rc::BeamTreeBuilder> beams_;
    mutable std::size_t beamsRead_ = 0;      ///< events beams_ has been given
    mutable std::uint64_t beamsSerial_ = 0;  ///< the serial() they belong to
    mutable std::unique_ptr<SampleFan> fan_;
    StepCheckpoints checkpoints_;
};

}  // namespace rc
