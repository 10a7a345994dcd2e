#include "stop_applier.h"

#include "compare_pane.h"
#include "frame_log.h"
#include "image_view.h"
#include "main_window.h"
#include "scene_view.h"
#include "toolbars.h"
#include "tour_player.h"

namespace rcgui {

StopApplier::StopApplier(MainWindow& window) : QObject(&window), w_(window) {}

void StopApplier::choose(const GuiOptions& o) {
    // Choose everything first, then build one session with these choices
    w_.setOverlays(o.overlays);
    w_.options_ = renderOptionsOf(o);
    w_.sizeChoice_ = o.width > 0 || o.height > 0 ? -1 : 0;
    w_.toolbars_->showChoices(w_.options_, w_.sizeChoice_);
    w_.compare_->choose(o.compare);
    w_.setMissFilter(o.missReason);
    if (o.panels) w_.showPanels(*o.panels);
    w_.selection_ = {};
}

// [apply-stop]
bool StopApplier::apply(const GuiOptions& o, bool wait) {
    FrameTask task("apply");
    // Whatever runs gives way to the new state
    pending_.reset();
    w_.setPlaying(false);
    for (SessionController* c : {&w_.controller_, &w_.compare_->controller()}) {
        c->cancel();
        c->wait();
    }
    choose(o);
    // A live window builds the render on the worker, which goes on to the stop's rays; it
    // takes a tour's render made ahead, with its scene, or goes on with its own if the same
    const bool onWorker = w_.workerSessions_ && !wait;
    w_.stepsOnReset_ = onWorker ? std::max<std::int64_t>(0, o.steps) : 0;
    w_.reuseOnReset_ = onWorker;
    if (auto scene = onWorker ? w_.tour_->aheadScene(o.scene) : nullptr; scene && scene != w_.scene_) {
        w_.scene_ = std::move(scene);
        w_.showScene(o.scene);
    }
    const bool loaded = (w_.scene_ && o.scene == w_.sceneSpec_) ? (w_.resetSession(), true) : w_.loadScene(o.scene);
    w_.stepsOnReset_ = 0;
    w_.reuseOnReset_ = false;
    if (!loaded) return false;
    if (onWorker) {
        pending_ = o;
        pendingRun_ = false;
        return true;
    }
    // The stop's rays, and on to the miss or deferral it shows: here when asked to wait,
    // else on the worker (the window stays live)
    if (rc::SessionState* s = w_.controller_.state()) s->setMissFilter(w_.missFilter_);
    if (!wait && (o.steps > 0 || o.runTo)) {
        pending_ = o;
        pendingRun_ = false;
        if (o.steps > 0) w_.controller_.goToStep(o.steps);
        else continuePending();
        return true;
    }
    if (rc::SessionState* s = w_.controller_.state()) {
        if (o.steps > 0) s->runUntil(rc::RunGoal::ToStep, o.steps);
        if (o.runTo) s->runUntil(*o.runTo, 0);
    }
    return finish(o, wait);
}

void StopApplier::onRunFinished(bool completed) {
    if (pending_ && completed) continuePending();
    else pending_.reset();
}

void StopApplier::continuePending() {
    if (pending_->runTo && !pendingRun_) {
        pendingRun_ = true;
        if (rc::SessionState* s = w_.controller_.state()) s->setMissFilter(w_.missFilter_);
        if (w_.controller_.start(*pending_->runTo)) return;
    }
    const GuiOptions o = *pending_;
    pending_.reset();
    finish(o, false);
}

bool StopApplier::finish(const GuiOptions& o, bool wait) {
    w_.compare_->sync(wait);
    w_.setHeatmap(o.heatmap);
    w_.setSceneView(o.sceneView);
    if (o.sceneView) {
        w_.sceneView_->setAngle(o.sceneAngle);
        w_.sceneView_->setOrbit(o.orbitYaw, o.orbitPitch);
    }
    w_.refresh();
    // The miss or deferral run to; else, the scene view with nothing selected: a ray worth
    // seeing from the side
    const rc::SessionState* s = w_.controller_.state();
    if (o.runTo && s && s->stopEvent() >= 0) w_.selectEvent(s->stopEvent());
    else if (o.firstImpression || (o.sceneView && o.select.x() < 0)) w_.focusShowcase();
    if (o.select.x() >= 0) {
        QString why;
        if (!w_.selectRay(o.select.x(), o.select.y(), o.selectPath, why)) {
            w_.reportError("Cannot select", "--select: " + why);
            return false;
        }
    }
    frameViews(o);
    emit w_.shown();
    return true;
}
// [apply-stop]

void StopApplier::frameViews(const GuiOptions& o) {
    ImageView* view = w_.view_;
    // The compared view follows the first's zoom and pan from here on
    if (w_.compare_->on()) w_.compare_->view()->fit();
    if (!o.focus.isEmpty()) {
        view->fitRect(QRectF(o.focus));
    } else if (o.zoom != 1.0) {
        // Zoom about the selected pixel, else the pixel of the ray being traced
        view->fit();
        QPointF centre(view->image().width() / 2.0, view->image().height() / 2.0);
        const rc::SessionState* s = w_.controller_.state();
        int pixel = w_.selection_.pixel;
        if (pixel < 0 && s && s->recorder().lastEvent()) pixel = s->recorder().lastEvent()->task.pixel;
        if (s && pixel >= 0) centre = QPointF(pixel % s->width() + 0.5, pixel / s->width() + 0.5);
        // The rectangle that, fitted, is `o.zoom` times the whole image's fit
        const double z = o.zoom * view->zoom();
        const QSizeF seen(view->width() / z, view->height() / z);
        view->fitRect(QRectF(centre - QPointF(seen.width(), seen.height()) / 2.0, seen));
    } else {
        view->fit();
    }
}

}  // namespace rcgui
