#include "tour_player.h"

#include <QComboBox>
#include <QLabel>
#include <QTimer>
#include <QToolBar>

#include "frame_log.h"
#include "main_window.h"
#include "scene/builtin_scenes.h"

namespace rcgui {

bool sameRender(const rc::SessionConfig& a, const rc::SessionConfig& b) {
    const rc::RenderOptions &x = a.options, &y = b.options;
    const rc::Sampling &p = x.shading.sampling, &q = y.shading.sampling;
    return a.scene == b.scene && a.checkpointEvery == b.checkpointEvery && x.width == y.width &&
           x.height == y.height && x.cache == y.cache && x.accel == y.accel && x.order == y.order &&
           x.shading.maxDepth == y.shading.maxDepth && x.shading.cutoff == y.shading.cutoff &&
           x.shading.ambient == y.shading.ambient && p.spp == q.spp && p.lightRadius == q.lightRadius &&
           p.shadowSamples == q.shadowSamples && p.glossDegrees == q.glossDegrees &&
           p.glossSamples == q.glossSamples && p.seed == q.seed && x.band == y.band && x.verify == y.verify &&
           x.rowBegin == y.rowBegin && x.rowEnd == y.rowEnd && x.pixelOffset == y.pixelOffset &&
           x.sampleEntries == y.sampleEntries;
}

TourPlayer::TourPlayer(MainWindow& window, QLabel* caption) : QObject(&window), w_(window), caption_(caption) {
    bar_ = buildBar();
    // The window idle on a stop: time to make the next one's renders
    connect(&w_, &MainWindow::shown, this, [this] {
        shown_ = true;
        QTimer::singleShot(0, this, &TourPlayer::onIdle);
    });
    for (SessionController* c : {&w_.controller(), &w_.compareController()})
        connect(c, &SessionController::busyChanged, this, [this](bool busy) {
            if (!busy) QTimer::singleShot(0, this, &TourPlayer::onIdle);
        });
    for (Ahead& a : ahead_)
        connect(&a.controller, &SessionController::finished, this, [this] {
            if (aheadStop_ > 0 && !aheadBusy()) emit aheadReady(aheadStop_);
        });
}

TourPlayer::~TourPlayer() { dropAhead(); }

QToolBar* TourPlayer::buildBar() {
    // Its own row at the top: where the lecture is, and the way on
    w_.addToolBarBreak(Qt::TopToolBarArea);
    auto* bar = new QToolBar("Tour", &w_);
    bar->setObjectName("tour");
    w_.addToolBar(Qt::TopToolBarArea, bar);
    QAction* back = bar->addAction("◀ Stop", &w_, &MainWindow::previousStop);
    back->setShortcuts({QKeySequence(Qt::Key_PageUp)});
    back->setShortcutContext(Qt::ApplicationShortcut);
    back->setToolTip("The previous stop (PageUp, as a presenter's clicker sends)");
    stopBox_ = new QComboBox(&w_);
    stopBox_->setFocusPolicy(Qt::NoFocus);
    stopBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    stopBox_->setToolTip("The tour's stops: choose one to go there");
    bar->addWidget(stopBox_);
    connect(stopBox_, &QComboBox::activated, this, [this](int i) { goToStop(i + 1, false); });
    QAction* next = bar->addAction("Stop ▶", &w_, &MainWindow::nextStop);
    next->setShortcuts({QKeySequence(Qt::Key_PageDown)});
    next->setShortcutContext(Qt::ApplicationShortcut);
    next->setToolTip("The next stop (PageDown, as a presenter's clicker sends)");
    QAction* again = bar->addAction("As written", &w_, &MainWindow::restoreStop);
    again->setShortcut(Qt::Key_R);
    again->setToolTip("Back to this stop as the tour wrote it, after stepping, selecting or toggling (R)");
    bar->hide();
    return bar;
}

void TourPlayer::setTour(const rc::Tour& tour, std::vector<GuiOptions> stops) {
    dropAhead();
    tour_ = tour;
    stops_ = std::move(stops);
    stop_ = 0;
    const QSignalBlocker b(stopBox_);
    stopBox_->clear();
    for (std::size_t i = 0; i < tour_.stops.size(); ++i)
        stopBox_->addItem(QString("%1/%2  %3").arg(i + 1).arg(tour_.stops.size()).arg(QString::fromStdString(tour_.stops[i].title)));
    bar_->setVisible(!stops_.empty());
    if (!tour_.title.empty()) w_.setWindowTitle(QString::fromStdString(tour_.title) + " — RayCache");
}

bool TourPlayer::goToStop(int stop, bool wait) {
    if (stop < 1 || stop > stopCount()) return false;
    FrameTask task(QString("stop-%1").arg(stop));
    stop_ = stop;
    {
        const QSignalBlocker b(stopBox_);
        stopBox_->setCurrentIndex(stop - 1);
    }
    const rc::TourStop& st = tour_.stops[std::size_t(stop - 1)];
    caption_->setText(QString("<b>%1/%2 &nbsp;%3.</b> %4")
                          .arg(stop).arg(stopCount())
                          .arg(QString::fromStdString(st.title).toHtmlEscaped(),
                               QString::fromStdString(st.caption).toHtmlEscaped()));
    caption_->show();
    // Renders made ahead for another stop are of no use now
    if (aheadStop_ != stop) dropAhead();
    pictureStart_ = FrameLog::now();
    pictureMs_ = -1.0;
    shown_ = false;
    const bool ok = w_.apply(stops_[std::size_t(stop - 1)], wait);
    dropAhead();  // what this stop did not take
    return ok;
}

QString TourPlayer::caption() const { return caption_->isVisible() || stop_ > 0 ? caption_->text() : QString(); }

void TourPlayer::setAhead(bool on) {
    aheadOn_ = on;
    if (!on) dropAhead();
}

bool TourPlayer::aheadBusy() const {
    for (const Ahead& a : ahead_)
        if (a.controller.busy()) return true;
    return false;
}

void TourPlayer::dropAhead() {
    for (Ahead& a : ahead_) {
        a.controller.clear();
        a.made = false;
        a.config = {};
    }
    aheadStop_ = 0;
}

std::shared_ptr<const rc::Scene> TourPlayer::aheadScene(const QString& spec) const {
    if (aheadStop_ < 1 || stops_[std::size_t(aheadStop_ - 1)].scene != spec) return nullptr;
    return ahead_[0].config.scene;
}

std::unique_ptr<rc::SessionState> TourPlayer::takeAhead(const rc::SessionConfig& config) {
    for (Ahead& a : ahead_) {
        if (!a.made || !sameRender(a.config, config)) continue;
        // Stopped where it is: the window goes on from there on its own worker
        std::unique_ptr<rc::SessionState> s = a.controller.take();
        a.made = false;
        if (s) ++taken_;
        return s;
    }
    return nullptr;
}

void TourPlayer::onIdle() {
    if (w_.controller().busy() || w_.compareController().busy()) return;
    if (shown_ && pictureStart_ >= 0.0) {
        pictureMs_ = FrameLog::now() - pictureStart_;
        pictureStart_ = -1.0;
        FrameLog::instance().record(QString("stop-%1-picture").arg(stop_), pictureMs_);
    }
    maybeMakeAhead();
}

void TourPlayer::maybeMakeAhead() {
    const int next = stop_ + 1;
    if (!aheadOn_ || !w_.workerSessions() || stop_ < 1 || next > stopCount() || aheadStop_ == next) return;
    if (w_.controller().busy() || w_.compareController().busy()) return;
    const GuiOptions& o = stops_[std::size_t(next - 1)];
    FrameTask task(QString("ahead-%1").arg(next));
    std::shared_ptr<const rc::Scene> scene = w_.sceneFor(o.scene);
    if (!scene) return;  // a bad scene: the stop reports it when it is reached
    rc::RenderOptions ro = renderOptionsOf(o);
    // The same render as this stop's: the stop goes on with the window's own
    if (const rc::SessionState* s = w_.controller().state(); s && sameRender(s->config(), {scene, ro})) return;
    dropAhead();
    aheadStop_ = next;
    const std::int64_t steps = std::max<std::int64_t>(0, o.steps);
    ahead_[0].config = {scene, ro};
    ahead_[0].made = true;
    ahead_[0].controller.resetOnWorker(ahead_[0].config, rc::RunGoal::ToStep, steps);
    if (o.compare) {
        ro.cache = o.compare->cache;
        ro.order = o.compare->order;
        ahead_[1].config = {scene, ro};
        ahead_[1].made = true;
        ahead_[1].controller.resetOnWorker(ahead_[1].config, rc::RunGoal::ToStep, steps);
    }
}

}  // namespace rcgui
