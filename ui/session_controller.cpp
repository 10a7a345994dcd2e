#include "session_controller.h"

#include <QCoreApplication>
#include <QThread>

namespace rcgui {

SessionController::SessionController(QObject* parent) : QObject(parent) {}

SessionController::~SessionController() {
    cancel();
    if (worker_) {
        worker_->wait();
        delete worker_;
        worker_ = nullptr;
    }
}

QImage SessionController::imageOf(const rc::SessionState& s) {
    const std::vector<std::uint8_t> rgb = s.session().image().rgb8();
    QImage img(s.width(), s.height(), QImage::Format_RGB888);
    for (int y = 0; y < s.height(); ++y)
        std::copy_n(rgb.data() + std::size_t(y) * s.width() * 3, std::size_t(s.width()) * 3,
                    img.scanLine(y));
    return img;
}

void SessionController::reset(rc::SessionConfig config) {
    cancel();
    wait();
    state_ = std::make_unique<rc::SessionState>(std::move(config));
    emit changed();
}

void SessionController::resetOnWorker(rc::SessionConfig config, rc::RunGoal goal, std::int64_t target) {
    cancel();
    wait();
    state_.reset();
    busy_ = true;
    cancel_ = false;
    emit busyChanged(true);
    const std::uint64_t run = ++run_;
    worker_ = QThread::create([this, config = std::move(config), goal, target, run]() mutable {
        std::unique_ptr<rc::SessionState> s;
        try {
            s = std::make_unique<rc::SessionState>(std::move(config));
        } catch (const std::exception& e) {
            // Said on the GUI thread; there is no state to hand back
            const QString why = QString::fromUtf8(e.what());
            workerResult_ = false;
            QMetaObject::invokeMethod(this, [this, why, run] {
                if (!busy_ || run != run_) return;
                onWorkerDone(false);
                emit failed(why);
            }, Qt::QueuedConnection);
            return;
        }
        const bool ok = s->runUntil(goal, target, &cancel_, [this, st = s.get()] {
            const QImage img = imageOf(*st);
            const qint64 steps = st->session().steps();
            const double progress = st->session().progress();
            QMetaObject::invokeMethod(this, [this, img, steps, progress] {
                if (busy_) emit snapshot(img, steps, progress);
            }, Qt::QueuedConnection);
        });
        made_ = std::move(s);
        workerResult_ = ok;
        QMetaObject::invokeMethod(this, [this, ok, run] {
            if (busy_ && run == run_) onWorkerDone(ok);
        }, Qt::QueuedConnection);
    });
    worker_->start();
}

void SessionController::clear() {
    cancel();
    wait();
    state_.reset();
    emit changed();
}

std::unique_ptr<rc::SessionState> SessionController::take() {
    cancel();
    wait();
    return std::move(state_);
}

void SessionController::adopt(std::unique_ptr<rc::SessionState> state) {
    cancel();
    wait();
    state_ = std::move(state);
    emit changed();
}

bool SessionController::stepRay() {
    if (busy_ || !state_) return false;
    const bool more = state_->step();
    emit changed();
    return more;
}

bool SessionController::start(rc::RunGoal goal, std::int64_t target) { return launch(goal, target, -1); }

bool SessionController::launch(rc::RunGoal goal, std::int64_t target, std::int64_t rewindTo) {
    if (busy_ || !state_) return false;
    busy_ = true;
    cancel_ = false;
    emit busyChanged(true);
    rc::SessionState* s = state_.get();
    const std::uint64_t run = ++run_;
    worker_ = QThread::create([this, s, goal, target, run, rewindTo] {
        // [go-back]
        // Going back: to the latest checkpoint at or before the step, then forwards
        std::int64_t from = -1;
        if (rewindTo >= 0) {
            s->rewindTo(rewindTo);
            from = s->session().steps();
        }
        // [go-back]
        const bool ok = s->runUntil(goal, target, &cancel_, [this, s] {
            // The worker owns the state: it alone may read it, so it makes the snapshot
            const QImage img = imageOf(*s);
            const qint64 steps = s->session().steps();
            const double progress = s->session().progress();
            QMetaObject::invokeMethod(this, [this, img, steps, progress] {
                if (busy_) emit snapshot(img, steps, progress);
            }, Qt::QueuedConnection);
        });
        if (from >= 0) replayed_ = s->session().steps() - from;
        workerResult_ = ok;
        // The hand-back; wait() may have taken it already (then run_ has moved on or busy_ is off)
        QMetaObject::invokeMethod(this, [this, ok, run] {
            if (busy_ && run == run_) onWorkerDone(ok);
        }, Qt::QueuedConnection);
    });
    worker_->start();
    return true;
}

bool SessionController::stepBack() {
    if (busy_ || !state_) return false;
    const std::int64_t target = state_->session().steps() - 1;
    if (target < 0) return false;
    return goToStep(target);
}

bool SessionController::goToStep(std::int64_t step) {
    if (busy_ || !state_ || step < 0) return false;
    // Backwards: the core is deterministic, so the render replayed from a checkpoint
    // before `step` is the render as it was at that step
    if (step < state_->session().steps()) return launch(rc::RunGoal::ToStep, step, step);
    return start(rc::RunGoal::ToStep, step);
}

void SessionController::cancel() { cancel_ = true; }

void SessionController::wait() {
    // No event loop here: spinning one would run the user's clicks (and this very call
    // again) in the middle of whatever called wait(). The worker's result is read directly.
    if (!busy_ || !worker_) return;
    worker_->wait();
    onWorkerDone(workerResult_.load());
}

void SessionController::onWorkerDone(bool completed) {
    if (worker_) {
        worker_->wait();
        delete worker_;
        worker_ = nullptr;
    }
    // A render built on the worker is the state from now on
    if (made_) state_ = std::move(made_);
    busy_ = false;
    emit busyChanged(false);
    emit finished(completed);
    emit changed();
}

}  // namespace rcgui
