#pragma once
/// \file
/// \brief Owns the GUI's render and runs long stretches of it on a worker thread.
#include <atomic>
#include <memory>

#include <QImage>
#include <QObject>

#include "view/session_state.h"

class QThread;

namespace rcgui {

/// Owns the current SessionState. While a worker runs, the worker alone touches the
/// state: state() returns null, and the GUI sees the render through snapshot()
/// images. When the worker stops, it hands the state back and finished() is emitted.
class SessionController : public QObject {
    Q_OBJECT
public:
    explicit SessionController(QObject* parent = nullptr);
    ~SessionController() override;

    /// Starts a new render (cancels a running worker first).
    void reset(rc::SessionConfig config);
    /// Starts a new render on the worker: builds it there (a large scene's blocker lists
    /// take long), then runs towards `goal`; the state is handed back as a run's is.
    void resetOnWorker(rc::SessionConfig config, rc::RunGoal goal = rc::RunGoal::ToStep, std::int64_t target = 0);
    /// The state, or null while a worker runs or before the first reset().
    rc::SessionState* state() { return busy_ ? nullptr : state_.get(); }
    const rc::SessionState* state() const { return busy_ ? nullptr : state_.get(); }
    bool busy() const { return busy_; }

    /// Stops any worker and drops the state (state() is null afterwards).
    void clear();
    /// Stops any worker where it is and hands the state over (null if there is none).
    std::unique_ptr<rc::SessionState> take();
    /// Makes `state` (a render made elsewhere, e.g. by another controller) the render.
    void adopt(std::unique_ptr<rc::SessionState> state);
    /// Traces one ray on the calling (GUI) thread. False if busy or done.
    bool stepRay();
    /// Runs towards `goal` on a worker thread. False if busy.
    bool start(rc::RunGoal goal, std::int64_t target = 0);
    /// Goes back one step, on the worker: back to the latest checkpoint before it, then
    /// forwards. The core is deterministic, so the state is the one of that step.
    bool stepBack();
    /// Runs forwards to step `step`, or, when it lies behind, goes back to the latest
    /// checkpoint at or before it and replays the rest (SessionState::rewindTo).
    bool goToStep(std::int64_t step);
    /// Steps the last step back (or go to step backwards) replayed after its checkpoint.
    std::int64_t replayed() const { return replayed_; }
    /// Asks the worker to stop; it hands the state back soon after.
    void cancel();
    /// Blocks until the worker has stopped, then takes the state back (emitting
    /// finished() and changed()). Runs no event loop, so it cannot be re-entered.
    void wait();

    /// The image as rgb8 converted to a QImage (the caller must not be racing a worker).
    static QImage imageOf(const rc::SessionState& s);

signals:
    /// The state changed (a step, a reset, a finished run): everything should refresh.
    void changed();
    void busyChanged(bool busy);
    /// A worker's view of the image while it runs, and its step count.
    void snapshot(const QImage& image, qint64 steps, double progress);
    /// A worker stopped: `completed` is false when it was cancelled.
    void finished(bool completed);
    /// resetOnWorker() could not build the render: why.
    void failed(const QString& why);

private:
    void onWorkerDone(bool completed);
    /// start(), going back to the last checkpoint at or before `rewindTo` first (-1: not).
    bool launch(rc::RunGoal goal, std::int64_t target, std::int64_t rewindTo);
    std::unique_ptr<rc::SessionState> state_;
    std::unique_ptr<rc::SessionState> made_;  ///< built by resetOnWorker()'s worker, not yet handed back
    QThread* worker_ = nullptr;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> workerResult_{false};
    std::atomic<std::int64_t> replayed_{0};
    std::uint64_t run_ = 0;  ///< the run a queued hand-back belongs to
    bool busy_ = false;
};

}  // namespace rcgui
