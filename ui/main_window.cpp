#include "main_window.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QScreen>
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>

#include "compare_pane.h"
#include "event_log_panel.h"
#include "frame_log.h"
#include "geometry/student_code.h"
#include "heatmap_builder.h"
#include "image_view.h"
#include "objects_panel.h"
#include "panels.h"
#include "presentation_mode.h"
#include "player.h"
#include "ray_selector.h"
#include "ray_tree_panel.h"
#include "run_progress.h"
#include "scene/builtin_scenes.h"
#include "scene_view.h"
#include "stats_panel.h"
#include "stop_applier.h"
#include "toolbars.h"
#include "tour_player.h"
#include "view/overlay_layers.h"

namespace rcgui {

namespace {
// The window's first size, bounded by the screen (a 1280x720 projector)
constexpr QSize kFirstSize(1400, 900);
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QString("RayCache — caching and breadth-first search (Hanrahan 1986)") +
                   QString::fromStdString(rc::studentSummary().empty() ? "" : " — " + rc::studentSummary()));
    options_.cache = rc::CacheKind::Blocker;
    options_.order = rc::OrderKind::BreadthFirst;
    reportError_ = [this](const QString& title, const QString& message) { QMessageBox::critical(this, title, message); };
    buildViews();
    hookView();
    // Toolbars and panels, compare mode, presentation
    toolbars_ = new Toolbars(*this);
    panels_ = new Panels(*this);
    compare_->setBox(toolbars_->compareBox());
    presentation_ = new PresentationMode(*this, *panels_, overlays_);
    presentation_->setActions(toolbars_->presentAction(), toolbars_->largeFontsAction());
    connect(presentation_, &PresentationMode::fontsChanged, view_, qOverload<>(&QWidget::update));
    connect(panels_, &Panels::refreshDue, this, &MainWindow::refresh);
    connect(panels_->rayTree(), &RayTreePanel::rayChosen, this, &MainWindow::selectEvent);
    connect(panels_->eventLog(), &EventLogPanel::eventChosen, this, &MainWindow::selectEvent);
    connect(panels_->stats(), &StatsPanel::chartDue, this, &MainWindow::refresh);
    connect(panels_->eventLog(), &EventLogPanel::reasonChosen, this, [this](rc::MissReason r) { missFilter_ = r; });
    connect(panels_->objects(), &ObjectsPanel::objectChosen, this, &MainWindow::selectObject);
    applier_ = new StopApplier(*this);
    hookController();
    player_ = new Player(*this);
    selector_ = new RaySelector(*this);
    tour_ = new TourPlayer(*this, findChild<QLabel*>("tourCaption"));
    QSize size = kFirstSize;
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size());
    resize(size);
    updateControls();
}

MainWindow::~MainWindow() { stopRuns(); }

void MainWindow::stopRuns() {
    controller_.cancel();
    compare_->controller().cancel();
    controller_.wait();
    compare_->stop();
}

void MainWindow::buildViews() {
    // The views side by side: the image, the compared render's, the scene
    view_ = new ImageView(this);
    compare_ = new ComparePane(*this);
    sceneView_ = new SceneView(this);
    split_ = new QSplitter(Qt::Horizontal, this);
    split_->setObjectName("central");
    split_->addWidget(view_);
    split_->addWidget(compare_->view());
    split_->addWidget(sceneView_);
    split_->setChildrenCollapsible(false);
    sceneView_->hide();
    // A tour's caption above the views, in the font of the rest (large on a projector)
    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    auto* caption = new QLabel(central);
    caption->setObjectName("tourCaption");
    caption->setWordWrap(true);
    caption->setTextFormat(Qt::RichText);
    caption->setContentsMargins(10, 6, 10, 6);
    caption->setStyleSheet("QLabel#tourCaption { background: #1d2733; color: #f4f4f4; }");
    caption->hide();
    column->addWidget(caption);
    column->addWidget(split_, 1);
    setCentralWidget(central);
}

void MainWindow::hookView() {
    // The first render's overlays, key and tooltips
    view_->setOverlayHook([this](QPainter& p, double scale) {
        if (const rc::SessionState* s = controller_.state()) overlayPainter_.paint(p, *s, overlays_, selection_, scale);
    });
    view_->setLegendHook([this](QPainter& p, const QRectF& area) {
        if (const rc::SessionState* s = controller_.state()) {
            overlayPainter_.paintLegend(p, *s, overlays_, selection_, area, view_->shownImageRect());
            keepLegendBeside(view_, overlayPainter_);
        }
    });
    view_->setTooltipHook([this](int x, int y) { return pixelTooltip(controller_.state(), x, y); });
    connect(view_, &ImageView::pixelClicked, this, &MainWindow::selectPixel);
    connect(view_, &ImageView::cleared, this, [this] { selectPixel(-1, -1); });
}

void MainWindow::hookController() {
    connect(&controller_, &SessionController::changed, this, &MainWindow::refresh);
    connect(&controller_, &SessionController::failed, this, [this](const QString& why) { reportError_("Cannot start the render", why); });
    connect(&controller_, &SessionController::busyChanged, this, &MainWindow::onBusyChanged);
    // While the worker runs: its picture, and a progress bar with Cancel in the status bar
    progress_ = new RunProgress(*this);
    connect(progress_, &RunProgress::cancelClicked, this, &MainWindow::cancelRun);
    connect(&controller_, &SessionController::snapshot, this, [this](const QImage& img, qint64 steps, double progress) {
        view_->setImage(img);
        panels_->stats()->showProgress(steps, progress);
        progress_->show(steps, progress);
    });
    connect(&controller_, &SessionController::finished, this, [this](bool completed) {
        progress_->ended(completed);
        // Next miss / Next deferral: the ray in focus is the one they stopped on
        if (const rc::SessionState* s = controller_.state(); s && s->stopEvent() >= 0) selectEvent(s->stopEvent());
        // A stop's rays are traced: on to its miss, or show the rest of it
        applier_->onRunFinished(completed);
    });
}

void MainWindow::setSceneView(bool on) {
    sceneView_->setVisible(on);
    toolbars_->showSceneView(on);
    split_->setSizes(paneSizes(compare_->on(), on));
    viewsChanged();
}

void MainWindow::viewsChanged() {
    view_->update();
    if (compare_->on()) compare_->view()->update();
    if (!sceneView_->isHidden()) {
        sceneView_->setLayers(overlays_.cylinder, overlays_.hull, overlays_.samples);
        if (const rc::SessionState* s = controller_.state())
            sceneView_->setSketch(SceneSketch::of(*s, selection_, overlays_.samples));
    }
}

std::shared_ptr<const rc::Scene> MainWindow::sceneFor(const QString& spec) const {
    if (scene_ && spec == sceneSpec_) return scene_;
    try {
        return std::make_shared<const rc::Scene>(rc::loadScene(spec.toStdString()));
    } catch (const std::exception&) {
        return nullptr;
    }
}

bool MainWindow::loadScene(const QString& spec) {
    FrameTask task("load-scene");
    std::shared_ptr<const rc::Scene> scene;
    try {
        scene = std::make_shared<const rc::Scene>(rc::loadScene(spec.toStdString()));
    } catch (const std::exception& e) {
        reportError_("Cannot open scene", QString::fromUtf8(e.what()));
        // Keep the current scene, and show it as the current choice again
        if (scene_) {
            const int i = toolbars_->sceneBox()->findData(QString::fromStdString(scene_->name));
            if (i >= 0) toolbars_->sceneBox()->setCurrentIndex(i);
        }
        return false;
    }
    scene_ = std::move(scene);
    showScene(spec);
    selection_ = {};
    resetSession();
    return true;
}

void MainWindow::showScene(const QString& spec) {
    sceneSpec_ = spec;
    QComboBox* box = toolbars_->sceneBox();
    const QString key = QFileInfo::exists(spec) ? QFileInfo(spec).absoluteFilePath() : spec;
    int i = box->findData(key);
    if (i < 0) {
        box->addItem(QFileInfo::exists(spec) ? QFileInfo(spec).fileName() : spec, key);
        i = box->count() - 1;
    }
    box->setCurrentIndex(i);
    panels_->objects()->setScene(scene_.get());
}

void MainWindow::openSceneDialog() {
    const QString file = QFileDialog::getOpenFileName(this, "Open NFF scene", QString(), "NFF scenes (*.nff);;All files (*)");
    if (!file.isEmpty()) loadScene(file);
}

void MainWindow::setCache(rc::CacheKind k) {
    options_.cache = k;
    toolbars_->showChoices(options_, sizeChoice_);
    resetSession();
}

void MainWindow::setAccel(rc::AccelKind k) {
    options_.accel = k;
    toolbars_->showChoices(options_, sizeChoice_);
    resetSession();
}

void MainWindow::setOrder(rc::OrderKind k) {
    options_.order = k;
    toolbars_->showChoices(options_, sizeChoice_);
    resetSession();
}

void MainWindow::setSizeChoice(int longerSide) {
    sizeChoice_ = longerSide;
    resetSession();
}

void MainWindow::setImageSize(int width, int height) {
    options_.width = width;
    options_.height = height;
    sizeChoice_ = -1;
    resetSession();
}

void MainWindow::selectPixel(int x, int y) { selector_->selectPixel(x, y); }
bool MainWindow::selectEvent(int event) { return selector_->selectEvent(event); }
void MainWindow::selectObject(int object) { selector_->selectObject(object); }
int MainWindow::focusShowcase() { return selector_->focusShowcase(); }
bool MainWindow::selectRay(int x, int y, const QString& path, QString& error) { return selector_->selectRay(x, y, path, error); }

void MainWindow::resetSession() {
    if (!scene_) return;
    FrameTask task("new-session");
    setPlaying(false);
    // The image size may change: pixels selected in the old render mean nothing now
    selection_.pixel = selection_.event = -1;
    const rc::SessionConfig config{scene_, effectiveOptions()};
    if (compare_->on()) compare_->controller().clear();  // rebuilt with the new choices below
    const rc::SessionState* own = controller_.state();
    if (auto made = reuseOnReset_ ? tour_->takeAhead(config) : nullptr) {
        // A tour's render made ahead: on from where it got to, as a new render would go
        controller_.adopt(std::move(made));
        controller_.goToStep(stepsOnReset_);
    } else if (reuseOnReset_ && own && sameRender(own->config(), config)) {
        controller_.goToStep(stepsOnReset_);  // the same render: back or on to the step
    } else if (workerSessions_) {
        // Built on the worker when the window is live (and on to a stop's first rays)
        controller_.resetOnWorker(config, rc::RunGoal::ToStep, stepsOnReset_);
        ++rendersBuilt_;
    } else {
        try {
            controller_.reset(config);
            ++rendersBuilt_;
        } catch (const std::exception& e) {
            reportError_("Cannot start the render", QString::fromUtf8(e.what()));
        }
    }
    compare_->start();
    updateControls();
}

void MainWindow::setOverlays(const Overlays& o) {
    const double lineScale = overlays_.lineScale;
    overlays_ = o;
    overlays_.lineScale = lineScale;
    toolbars_->showOverlays(o);
    view_->setGridEnabled(o.grid);
    compare_->view()->setGridEnabled(o.grid);
    viewsChanged();
}

void MainWindow::setHeatmap(Heatmap h) {
    heatmap_ = h;
    overlayPainter_.setHeatmap(h, compare_->heatmapTop());
    toolbars_->showHeatmap(h);
    refresh();
}

void MainWindow::setPresentation(bool on) {
    presentation_->setPresenting(on);
    view_->fit();
}

void MainWindow::stepRay() { controller_.stepRay(); }
void MainWindow::stepPixel() { controller_.start(rc::RunGoal::NextPixel); }
void MainWindow::runToNextMiss() {
    if (rc::SessionState* s = controller_.state()) s->setMissFilter(missFilter_);
    controller_.start(rc::RunGoal::NextMiss);
}
void MainWindow::runToNextDeferral() { controller_.start(rc::RunGoal::NextDeferral); }
void MainWindow::goToStep(qint64 step) {
    setPlaying(false);
    controller_.goToStep(step);
}
void MainWindow::runToEnd() {
    setPlaying(false);
    controller_.start(rc::RunGoal::ToEnd);
}
void MainWindow::stepBack() {
    setPlaying(false);
    controller_.stepBack();
}
void MainWindow::cancelRun() {
    setPlaying(false);
    controller_.cancel();
}

void MainWindow::setPlaying(bool on) {
    if (toolbars_ && toolbars_->showPlaying(on)) return;  // back here through the button's toggle
    player_->setPlaying(on);
}

int MainWindow::beamPath() const {
    if (const rc::SessionState* s = controller_.state())
        if (const auto& e = s->recorder().lastCommitted()) return e->task.node;
    return 0;
}

void MainWindow::refresh() {
    const rc::SessionState* s = controller_.state();
    if (!s) return;
    const double top = compare_->heatmapTop();
    overlayPainter_.setHeatmap(heatmap_, top);
    {
        FrameTask task("refresh-image");
        view_->setImage(HeatmapBuilder::build(*s, heatmap_, beamPath(), top));
    }
    // Panels out of sight wait until they are shown (each dock refreshes when it appears)
    panels_->refresh(*s, compare_->on() ? compare_->controller().state() : nullptr, selection_);
    statusBar()->showMessage(QString("%1 steps%2").arg(s->session().steps()).arg(s->session().done() ? ", done" : "") +
                             QString::fromStdString(rc::cannotDrawYet().empty() ? "" : " — " + rc::cannotDrawYet()));
    updateControls();
    compare_->refresh();
    viewsChanged();
}

void MainWindow::onBusyChanged(bool busy) {
    progress_->setBusy(busy);
    if (busy) panels_->letGo();  // the worker owns the state now: let go of every view of it
    updateControls();
    view_->update();
}

void MainWindow::updateControls() { toolbars_->update(controller_.busy(), controller_.state(), player_->playing()); }

void MainWindow::closeEvent(QCloseEvent* e) {
    setPlaying(false);
    stopRuns();
    e->accept();
}

void MainWindow::setWorkerSessions(bool on) {
    workerSessions_ = on;
    panels_->stats()->setThrottled(on);
    // A long event log is read into the per-pixel layers over several paints (a
    // screenshot reads it all at once)
    const std::size_t budget = on ? kLayerEventsPerPaint : 0;
    overlayPainter_.setEventBudget(budget, [this] { QTimer::singleShot(0, view_, [this] { view_->update(); }); });
    ImageView* cv = compare_->view();
    compare_->painter().setEventBudget(budget, [cv] { QTimer::singleShot(0, cv, [cv] { cv->update(); }); });
}

void MainWindow::setMissFilter(rc::MissReason r) {
    missFilter_ = r;
    panels_->eventLog()->setReason(r);
}

}  // namespace rcgui
