#include "main_window.h"

#include <cmath>
#include <limits>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QWidgetAction>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include "order/order_registry.h"
#include "search/search_registry.h"
#include "view/compare_caption.h"
#include "view/scene_list.h"
#include "cache_tree_panel.h"
#include "geometry/student_code.h"
#include "event_log_panel.h"
#include "frame_log.h"
#include "heatmap_builder.h"
#include "image_view.h"
#include "view/overlay_layers.h"
#include "labels.h"
#include "objects_panel.h"
#include "ray_tree_panel.h"
#include "scene_view.h"
#include "scene/builtin_scenes.h"
#include "stats_panel.h"

namespace rcgui {

QString scenesFolder() {
    // RAYCACHE_SCENES overrides; else the folder configured at build time
    const QString env = qEnvironmentVariable("RAYCACHE_SCENES");
    if (!env.isEmpty()) return env;
#ifdef RAYCACHE_SCENES_DIR
    return QStringLiteral(RAYCACHE_SCENES_DIR);
#else
    return {};
#endif
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QString("RayCache — caching and breadth-first search (Hanrahan 1986)") +
                   QString::fromStdString(rc::studentSummary().empty() ? "" : " — " + rc::studentSummary()));
    options_.cache = rc::CacheKind::Blocker;
    options_.order = rc::OrderKind::BreadthFirst;
    reportError_ = [this](const QString& title, const QString& message) {
        QMessageBox::critical(this, title, message);
    };
    // The views side by side: the image, the compared render's, the scene
    view_ = new ImageView(this);
    compareView_ = new ImageView(this);
    sceneView_ = new SceneView(this);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName("central");
    split->addWidget(view_);
    split->addWidget(compareView_);
    split->addWidget(sceneView_);
    split->setChildrenCollapsible(false);
    split_ = split;
    compareView_->hide();
    sceneView_->hide();
    // A tour's caption above the views, in the font of the rest (large on a projector)
    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    tourCaption_ = new QLabel(central);
    tourCaption_->setObjectName("tourCaption");
    tourCaption_->setWordWrap(true);
    tourCaption_->setTextFormat(Qt::RichText);
    tourCaption_->setContentsMargins(10, 6, 10, 6);
    tourCaption_->setStyleSheet("QLabel#tourCaption { background: #1d2733; color: #f4f4f4; }");
    tourCaption_->hide();
    column->addWidget(tourCaption_);
    column->addWidget(split, 1);
    setCentralWidget(central);
    // The compared render: the same overlays, the selection carried over by pixel and path
    compareView_->setOverlayHook([this](QPainter& p, double scale) {
        if (const rc::SessionState* c = compare_.state(); c && compareChoice_)
            comparePainter_.paint(p, *c, overlays_, compareSelection(), scale);
    });
    compareView_->setLegendHook([this](QPainter& p, const QRectF& area) {
        if (const rc::SessionState* c = compare_.state(); c && compareChoice_) {
            comparePainter_.paintLegend(p, *c, overlays_, compareSelection(), area, compareView_->shownImageRect());
            keepLegendBeside(compareView_, comparePainter_);
        }
    });
    compareView_->setTooltipHook([this](int x, int y) { return pixelTooltip(compare_.state(), x, y); });
    connect(compareView_, &ImageView::pixelClicked, this, &MainWindow::selectPixel);
    connect(compareView_, &ImageView::cleared, this, [this] { selectPixel(-1, -1); });
    comparePainter_.setKeysShown(false);
    // The two views zoom and pan together: the same pixels side by side
    auto follow = [this](ImageView* from, ImageView* to) {
        connect(from, &ImageView::viewMoved, this, [this, from, to] {
            if (!compareChoice_ || followingView_ || to->isHidden() || from->image().size() != to->image().size()) return;
            followingView_ = true;
            // The same image point at the same place relative to each view's centre
            const QPointF shift = QPointF(to->width() - from->width(), to->height() - from->height()) / 2.0;
            to->setZoom(from->zoom(), from->pan() + shift);
            followingView_ = false;
        });
    };
    follow(view_, compareView_);
    follow(compareView_, view_);
    connect(&compare_, &SessionController::changed, this, &MainWindow::refreshCompare);
    connect(&compare_, &SessionController::snapshot, this, [this](const QImage& img, qint64, double) {
        if (heatmap_ == Heatmap::None) compareView_->setImage(img);
    });
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

    // Toolbars and panels
    buildToolbars();
    buildDocks();

    // The controllers' news: changes, failures, runs
    connect(&controller_, &SessionController::changed, this, &MainWindow::refresh);
    connect(&controller_, &SessionController::failed, this, [this](const QString& why) {
        reportError_("Cannot start the render", why);
    });
    connect(&compare_, &SessionController::failed, this, [this](const QString& why) {
        reportError_("Cannot start the compared render", why);
    });
    connect(&controller_, &SessionController::busyChanged, this, &MainWindow::onBusyChanged);
    // While the worker runs: its picture, and a progress bar with Cancel in the status bar
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setMaximumWidth(260);
    progress_->setFormat("%p% of the eye rays");
    progressCancel_ = new QPushButton("Cancel", this);
    progressCancel_->setToolTip("Stop the run (Escape); what is traced so far stays");
    connect(progressCancel_, &QPushButton::clicked, this, &MainWindow::cancelRun);
    statusBar()->addPermanentWidget(progress_);
    statusBar()->addPermanentWidget(progressCancel_);
    progress_->hide();
    progressCancel_->hide();
    connect(&controller_, &SessionController::snapshot, this, [this](const QImage& img, qint64 steps, double progress) {
        view_->setImage(img);
        stats_->showProgress(steps, progress);
        progress_->setValue(int(std::lround(1000.0 * progress)));
        statusBar()->showMessage(QString("running… %1 steps").arg(steps));
    });
    connect(&controller_, &SessionController::finished, this, [this](bool completed) {
        statusBar()->showMessage(completed ? "run finished" : "run cancelled", 5000);
        // Next miss / Next deferral: the ray in focus is the one they stopped on
        if (const rc::SessionState* s = controller_.state(); s && s->stopEvent() >= 0) selectEvent(s->stopEvent());
        // A stop's rays are traced: on to its miss, or show the rest of it
        if (pending_ && completed) continuePending();
        else pending_.reset();
    });
    // Play, the tour bar, a size that fits the screen
    playTimer_.setInterval(33);
    connect(&playTimer_, &QTimer::timeout, this, &MainWindow::onPlayTick);
    buildTourBar();
    // Never larger than the screen (a 1280x720 projector)
    QSize size(1400, 900);
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size());
    resize(size);
    updateControls();
}

MainWindow::~MainWindow() {
    controller_.cancel();
    compare_.cancel();
    controller_.wait();
    compare_.wait();
}

void MainWindow::keepLegendBeside(ImageView* view, const OverlayPainter& painter) {
    // The caption and key go beside the fitted image, never over it: the view keeps room
    // for them, shrinking the image by at most a third of the view's width (a wider key
    // wraps its lines)
    const QSizeF image = view->image().size();
    const double fitted = image.isEmpty() ? 0.0 : image.width() * std::min(view->width() / image.width(), view->height() / image.height());
    const double room = std::max(0.0, view->width() - fitted);
    double want = std::min(painter.legendWidth(), std::max(room, view->width() / 3.0));
    // Too narrow to wrap into: the key goes over the picture, which keeps the whole view
    if (want < painter.legendMinBeside()) want = 0.0;
    if (std::abs(want - view->reserve()) > 8.0)
        QTimer::singleShot(0, view, [view, want] { view->setReserve(want); });
}

QLabel* MainWindow::toolbarLabel(const QString& text) {
    auto* l = new QLabel(" " + text + " ", this);
    l->setObjectName("toolbarLabel");
    return l;
}

QString pixelTooltip(const rc::SessionState* s, int x, int y) {
    if (!s || x < 0 || y < 0 || x >= s->width() || y >= s->height()) return {};
    const rc::TraceRecorder& rec = s->recorder();
    const int px = y * s->width() + x;
    if (rec.firstVisit(px) < 0) return QString("pixel (%1,%2): not traced yet").arg(x).arg(y);
    QString t = QString("pixel (%1,%2): %3 tests, %4 hits, %5 misses, first ray at step %6")
                    .arg(x).arg(y).arg(rec.testsAt(px)).arg(rec.hitsAt(px)).arg(rec.missesAt(px))
                    .arg(rec.firstVisit(px));
    if (rec.missReasonAt(px) != rc::MissReason::None)
        t += QString(", first miss: %1").arg(QString::fromUtf8(rc::toString(rec.missReasonAt(px)).data()));
    const std::optional<double> rate = HeatmapBuilder::hitRate(*s, px);
    t += rate ? QString(", hit rate %1% (%2 of %3 lookups)")
                    .arg(100.0 * *rate, 0, 'f', 1).arg(rec.hitsAt(px)).arg(rec.hitsAt(px) + rec.missesAt(px))
              : QString(", hit rate: no cache lookups");
    return t;
}

rc::Selection MainWindow::compareSelection() const {
    // The same pixel; the chosen ray carried over by its pixel and path
    rc::Selection sel = selection_;
    sel.event = -1;
    const rc::SessionState* s = controller_.state();
    const rc::SessionState* c = compare_.state();
    if (!c || sel.pixel >= c->width() * c->height()) return {};
    if (s && selection_.event >= 0 && std::size_t(selection_.event) < s->recorder().events().size()) {
        const rc::EventRecord& r = s->recorder().events()[std::size_t(selection_.event)];
        sel.event = c->recorder().eventAt(r.pixel, r.node);
        if (sel.event < 0) sel.pixel = r.pixel;
    }
    return sel;
}

double MainWindow::heatmapTop() const {
    // Two renders side by side share one scale: the larger of their own
    if (!compareChoice_ || (heatmap_ != Heatmap::Tests && heatmap_ != Heatmap::VisitOrder)) return 0.0;
    const rc::SessionState* s = controller_.state();
    const rc::SessionState* c = compare_.state();
    if (!s || !c) return 0.0;
    return std::max(HeatmapBuilder::scaleOf(*s, heatmap_), HeatmapBuilder::scaleOf(*c, heatmap_));
}

rc::RenderOptions MainWindow::effectiveOptions() const {
    rc::RenderOptions o = options_;
    if (sizeChoice_ >= 0 && scene_) {
        o.width = o.height = 0;
        if (sizeChoice_ > 0) {
            const int w = scene_->camera.width, h = scene_->camera.height;
            const double longer = std::max(w, h);
            o.width = std::max(1, int(std::lround(sizeChoice_ * w / longer)));
            o.height = std::max(1, int(std::lround(sizeChoice_ * h / longer)));
        }
    }
    return o;
}

bool MainWindow::setCompare(const QString& spec, QString& error) {
    auto showChoice = [this] {
        const QSignalBlocker b(compareBox_);
        const int i = compareChoice_ ? compareBox_->findData(toString(*compareChoice_)) : 0;
        compareBox_->setCurrentIndex(std::max(0, i));
    };
    const QString t = spec.trimmed().toLower();
    if (t.isEmpty() || t == "off") {
        compareChoice_.reset();
        compare_.clear();
        compareView_->hide();
        comparePainter_.setExtraCaption({});
        showChoice();
        refresh();
        return true;
    }
    const auto choice = parseCompare(spec, error);
    if (!choice) {
        showChoice();  // keeps what was there
        return false;
    }
    compareChoice_ = choice;
    compareView_->show();
    showChoice();
    startCompare();
    return true;
}

void MainWindow::startCompare() {
    if (!compareChoice_ || !scene_) return;
    rc::RenderOptions o = effectiveOptions();
    o.cache = compareChoice_->cache;
    o.order = compareChoice_->order;
    if (workerSessions_) {
        compare_.resetOnWorker({scene_, o});
    } else {
        try {
            compare_.reset({scene_, o});
        } catch (const std::exception& e) {
            reportError_("Cannot start the compared render", QString::fromUtf8(e.what()));
        }
    }
    split_->setSizes({1000, 1000, sceneView_->isHidden() ? 0 : 1000});
    compareView_->fit();
}

// [compare-sync]
void MainWindow::syncCompare(bool now) {
    if (!compareChoice_) return;
    const rc::SessionState* s = controller_.state();
    if (!s) return;  // the first render is running: catch up when it hands its state back
    if (now && compare_.busy()) compare_.wait();
    rc::SessionState* c = compare_.state();
    if (!c) return;  // the compared render is catching up on its worker
    const std::int64_t want = s->session().steps(), have = c->session().steps();
    if (want == have) {
        // Every render has the same rays: when the first is done, so is the second
        if (s->session().done() && !c->session().done()) c->step();
        return;
    }
    // A short way forwards (a step, a play tick) on this thread; else on the worker,
    // rebuilding and replaying when it lies behind
    constexpr std::int64_t kOnThisThread = 2000;
    if (want > have && (now || want - have <= kOnThisThread)) {
        c->runUntil(rc::RunGoal::ToStep, want);
        return;
    }
    compare_.goToStep(want);
    if (now) compare_.wait();
}
// [compare-sync]

void MainWindow::refreshCompare() {
    if (!compareChoice_) return;
    syncCompare();
    const rc::SessionState* c = compare_.state();
    const rc::SessionState* s = controller_.state();
    if (!c) return;
    const double top = heatmapTop();
    int path = 0;
    if (const auto& e = c->recorder().lastCommitted()) path = e->task.node;
    compareView_->setImage(HeatmapBuilder::build(*c, heatmap_, path, top));
    comparePainter_.setHeatmap(heatmap_, top);
    overlayPainter_.setHeatmap(heatmap_, top);
    QStringList extra;
    if (s) {
        // The core's lines (rc::compareCaption), as the page's
        for (const std::string& line : rc::compareCaption(*s, *c)) extra << QString::fromStdString(line);
        stats_->refresh(s, c);
    }
    comparePainter_.setExtraCaption(extra);
    compareView_->update();
    view_->update();
}

void MainWindow::setSceneView(bool on) {
    sceneView_->setVisible(on);
    if (sceneViewAct_ && sceneViewAct_->isChecked() != on) {
        const QSignalBlocker b(sceneViewAct_);
        sceneViewAct_->setChecked(on);
    }
    split_->setSizes({1000, compareView_->isHidden() ? 0 : 1000, on ? 1000 : 0});
    viewsChanged();
}

void MainWindow::viewsChanged() {
    view_->update();
    if (compareChoice_) compareView_->update();
    if (!sceneView_->isHidden()) {
        sceneView_->setLayers(overlays_.cylinder, overlays_.hull, overlays_.samples);
        if (const rc::SessionState* s = controller_.state())
            sceneView_->setSketch(SceneSketch::of(*s, selection_, overlays_.samples));
    }
}

void MainWindow::buildToolbars() {
    // Scene and render choices
    QToolBar* render = addToolBar("Render");
    render->setObjectName("render");
    sceneBox_ = new QComboBox(this);
    sceneBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    sceneBox_->setMinimumContentsLength(10);
    // Built-ins (cube:N and balls:N in the sizes the core suggests), then every scene of the
    // project's scenes/ folder: the core's list (rc::sceneChoices), as the page's
    for (const rc::SceneChoice& c : rc::sceneChoices(QDir(scenesFolder()).absolutePath().toStdString())) {
        sceneBox_->addItem(QString::fromStdString(c.label), QString::fromStdString(c.spec));
        sceneBox_->setItemData(sceneBox_->count() - 1, QString::fromStdString(c.description), Qt::ToolTipRole);
    }
    sceneBox_->setToolTip("Scene: built-ins, or files opened with Open…");
    render->addWidget(toolbarLabel("Scene"));
    render->addWidget(sceneBox_);
    openAct_ = render->addAction("Open…", this, &MainWindow::openSceneDialog);
    openAct_->setShortcut(QKeySequence::Open);
    connect(sceneBox_, &QComboBox::activated, this, [this](int i) { loadScene(sceneBox_->itemData(i).toString()); });

    // The cache
    cacheBox_ = new QComboBox(this);
    cacheBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    // Every cache, RayCache's blocker+ and blocker+dir beside the paper's two
    for (auto k : rc::allCacheKinds()) cacheBox_->addItem(text(rc::toString(k)), int(k));
    cacheBox_->setCurrentIndex(cacheBox_->findData(int(rc::CacheKind::Blocker)));
    render->addWidget(toolbarLabel("Cache"));
    render->addWidget(cacheBox_);
    connect(cacheBox_, &QComboBox::activated, this, [this](int i) { setCache(rc::CacheKind(cacheBox_->itemData(i).toInt())); });

    // The order
    orderBox_ = new QComboBox(this);
    orderBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (std::size_t k = 0; k < rc::orderRegistry().size(); ++k)  // every registered order
        orderBox_->addItem(text(rc::orderRegistry()[k].name), int(k));
    orderBox_->setCurrentIndex(2);
    orderBox_->setToolTip("progressive: all eye rays first, then deeper rays (the paper's conclusion)");
    render->addWidget(toolbarLabel("Order"));
    render->addWidget(orderBox_);
    connect(orderBox_, &QComboBox::activated, this, [this](int i) { setOrder(rc::OrderKind(orderBox_->itemData(i).toInt())); });

    // The complete search
    accelBox_ = new QComboBox(this);
    accelBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (std::size_t k = 0; k < rc::searchRegistry().size(); ++k)  // every exact complete search
        if (!rc::searchRegistry()[k].comparisonOnly) accelBox_->addItem(text(rc::searchRegistry()[k].name), int(k));
    accelBox_->setToolTip("What answers the complete searches: a linear scan, a uniform grid or a BVH");
    render->addWidget(toolbarLabel("Search"));
    render->addWidget(accelBox_);
    connect(accelBox_, &QComboBox::activated, this, [this](int i) { setAccel(rc::AccelKind(accelBox_->itemData(i).toInt())); });

    // The image size
    sizeBox_ = new QComboBox(this);
    sizeBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    sizeBox_->addItem("scene's", 0);
    for (int n : {32, 64, 128, 256, 512, 1024}) sizeBox_->addItem(QString::number(n), n);
    render->addWidget(toolbarLabel("Size"));
    render->addWidget(sizeBox_);
    connect(sizeBox_, &QComboBox::activated, this, [this](int i) {
        sizeChoice_ = sizeBox_->itemData(i).toInt();
        resetSession();
    });
    // A second render to compare with
    compareBox_ = new QComboBox(this);
    compareBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    compareBox_->setMinimumContentsLength(12);
    compareBox_->addItem("off", "off");
    for (auto c : rc::allCacheKinds())
        for (auto o : rc::allOrderKinds())
            compareBox_->addItem(toString(CompareChoice{c, o}), toString(CompareChoice{c, o}));
    compareBox_->setToolTip("Compare: run a second render with another cache and order beside this one, in lockstep");
    render->addWidget(toolbarLabel("Compare"));
    render->addWidget(compareBox_);
    connect(compareBox_, &QComboBox::activated, this, [this](int i) {
        QString why;
        if (!setCompare(compareBox_->itemData(i).toString(), why)) reportError_("Cannot compare", why);
    });
    resetAct_ = render->addAction("Reset", this, &MainWindow::resetSession);

    // Stepping
    addToolBarBreak();
    QToolBar* step = addToolBar("Step");
    step->setObjectName("step");
    // Step a ray, a pixel, to the next miss or deferral, to a step, back
    stepRayAct_ = step->addAction("Step ray", this, &MainWindow::stepRay);
    stepRayAct_->setShortcut(Qt::Key_Space);
    stepRayAct_->setToolTip("Trace exactly one ray (Space)");
    stepPixelAct_ = step->addAction("Step pixel", this, &MainWindow::stepPixel);
    stepPixelAct_->setToolTip("Trace until a ray of another pixel is traced");
    nextMissAct_ = step->addAction("Next miss", this, &MainWindow::runToNextMiss);
    nextMissAct_->setShortcut(Qt::Key_M);
    nextMissAct_->setToolTip("Trace until a cache miss (of the reason the event log chooses), and focus on it (M)");
    nextDeferralAct_ = step->addAction("Next deferral", this, &MainWindow::runToNextDeferral);
    nextDeferralAct_->setShortcut(Qt::Key_D);
    nextDeferralAct_->setToolTip("Trace until a ray is deferred (its cheap test failed), and focus on it (D)");
    goToAct_ = step->addAction("Go to step…", this, [this] {
        const rc::SessionState* s = controller_.state();
        if (!s) return;
        bool ok = false;
        const qint64 n = QInputDialog::getInt(this, "Go to step", "Step:", int(s->session().steps()), 0,
                                              std::numeric_limits<int>::max(), 1, &ok);
        if (ok) goToStep(n);
    });
    goToAct_->setShortcut(Qt::CTRL | Qt::Key_G);
    backAct_ = step->addAction("Step back", this, &MainWindow::stepBack);
    backAct_->setShortcut(Qt::Key_Backspace);
    backAct_->setToolTip("Rebuild and replay to one step before (the core is deterministic)");
    // Play at a speed, run to the end, cancel
    playAct_ = step->addAction("Play");
    playAct_->setCheckable(true);
    connect(playAct_, &QAction::toggled, this, &MainWindow::setPlaying);
    speed_ = new QSlider(Qt::Horizontal, this);
    speed_->setRange(0, 100);
    speed_->setValue(40);
    speed_->setMaximumWidth(160);
    speedLabel_ = new QLabel(this);
    auto showSpeed = [this](int v) { speedLabel_->setText(QString(" %1 rays/s ").arg(std::round(std::pow(10.0, v / 25.0)))); };
    showSpeed(speed_->value());
    connect(speed_, &QSlider::valueChanged, this, showSpeed);
    step->addWidget(speed_);
    step->addWidget(speedLabel_);
    runAct_ = step->addAction("Run to end", this, &MainWindow::runToEnd);
    cancelAct_ = step->addAction("Cancel", this, &MainWindow::cancelRun);
    cancelAct_->setShortcut(Qt::Key_Escape);

    // What to show: a row of its own, so that nothing spills into an overflow menu
    addToolBarBreak();
    QToolBar* show = addToolBar("Show");
    show->setObjectName("show");
    // The overlays, a check box each
    auto box = [&](const QString& label, const QString& tip, bool Overlays::*field) {
        auto* c = new QCheckBox(label, this);
        c->setToolTip(tip);
        c->setChecked(overlays_.*field);
        connect(c, &QCheckBox::toggled, this, [this, field](bool on) {
            overlays_.*field = on;
            view_->setGridEnabled(overlays_.grid);
            compareView_->setGridEnabled(overlays_.grid);
            viewsChanged();
        });
        show->addWidget(c);
        return c;
    };
    cylinderBox_ = box("Cylinder", "Cylinder of safety of the active cache entry", &Overlays::cylinder);
    hullBox_ = box("Hull", "Blocker hull of origin and target, its blockers (orange) and target (green)", &Overlays::hull);
    frontierBox_ = box("Frontier", "Breadth-first queue, deferred seeds and regions", &Overlays::frontier);
    missesBox_ = box("Misses", "Where misses happened, coloured by reason", &Overlays::misses);
    samplesBox_ = box("Samples", "The sample rays of the pixel in focus: its eye samples, the shadow rays of each hit "
                                 "fanning to the light's sphere (reaching it or blocked), its glossy reflections",
                      &Overlays::samples);
    gridBox_ = box("Grid", "Pixel grid at high zoom", &Overlays::grid);
    legendBox_ = box("Legend", "The colour key (beside the image when there is room)", &Overlays::legend);
    const QList<QAction*> shown = show->actions();
    cylinderAct_ = shown.value(0);
    hullAct_ = shown.value(1);
    frontierAct_ = shown.value(2);
    missesAct_ = shown.value(3);
    // The heatmap in place of the image
    heatmapBox_ = new QComboBox(this);
    heatmapBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    heatmapBox_->addItem("image", int(Heatmap::None));
    heatmapBox_->addItem("tests per pixel", int(Heatmap::Tests));
    heatmapBox_->addItem("hits / misses", int(Heatmap::HitMiss));
    heatmapBox_->addItem("cache hit rate", int(Heatmap::HitRate));
    heatmapBox_->addItem("visiting order", int(Heatmap::VisitOrder));
    heatmapBox_->addItem("beam-tree node", int(Heatmap::BeamNode));
    show->addWidget(toolbarLabel("Show"));
    show->addWidget(heatmapBox_);
    connect(heatmapBox_, &QComboBox::activated, this, [this](int i) { setHeatmap(Heatmap(heatmapBox_->itemData(i).toInt())); });
    // Fonts, presentation, the scene view, fit
    QAction* large = show->addAction("Large fonts");
    large->setCheckable(true);
    large->setToolTip("Bigger text for a projector");
    connect(large, &QAction::toggled, this, &MainWindow::setLargeFonts);
    presentAct_ = show->addAction("Present");
    presentAct_->setCheckable(true);
    presentAct_->setShortcut(Qt::Key_F11);
    presentAct_->setToolTip("Presentation mode: hide the panels, large fonts (F11)");
    connect(presentAct_, &QAction::toggled, this, &MainWindow::setPresentation);
    largeAct_ = large;
    sceneViewAct_ = show->addAction("Scene view");
    sceneViewAct_->setCheckable(true);
    sceneViewAct_->setToolTip("Show the 3D scene from the side: objects, lights, the ray tree in focus, its cylinder and hull");
    connect(sceneViewAct_, &QAction::toggled, this, &MainWindow::setSceneView);
    QAction* fit = show->addAction("Fit", view_, &ImageView::fit);
    fit->setToolTip("Fit the image to the window (F)");
}

void MainWindow::buildDocks() {
    auto dock = [&](const QString& title, QWidget* w, Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(title);
        d->setWidget(w);
        addDockWidget(area, d);
        return d;
    };
    rayTree_ = new RayTreePanel(this);
    cacheTree_ = new CacheTreePanel(this);
    stats_ = new StatsPanel(this);
    eventLog_ = new EventLogPanel(this);
    objects_ = new ObjectsPanel(this);
    // The right-hand panels run the window's full height and the event log sits under the
    // image only: stacked under both, they made the window taller than a 1280x720
    // projector with large fonts (818 pixels)
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    QDockWidget* rt = dock("Ray tree", rayTree_, Qt::RightDockWidgetArea);
    QDockWidget* ct = dock("Cache tree", cacheTree_, Qt::RightDockWidgetArea);
    QDockWidget* st = dock("Statistics", stats_, Qt::RightDockWidgetArea);
    QDockWidget* log = dock("Event log", eventLog_, Qt::BottomDockWidgetArea);
    QDockWidget* obj = dock("Objects", objects_, Qt::BottomDockWidgetArea);
    docks_ = {rt, ct, st, log, obj};  // in panelNames()' order
    for (QDockWidget* d : docks_)
        connect(d, &QDockWidget::visibilityChanged, this, [this](bool shown) {
            if (shown) QTimer::singleShot(0, this, &MainWindow::refresh);
        });
    tabifyDockWidget(rt, ct);
    rt->raise();
    tabifyDockWidget(log, obj);
    log->raise();
    resizeDocks({rt}, {520}, Qt::Horizontal);
    resizeDocks({log}, {180}, Qt::Vertical);
    connect(rayTree_, &RayTreePanel::rayChosen, this, &MainWindow::selectEvent);
    connect(eventLog_, &EventLogPanel::eventChosen, this, &MainWindow::selectEvent);
    connect(stats_, &StatsPanel::chartDue, this, &MainWindow::refresh);
    connect(eventLog_, &EventLogPanel::reasonChosen, this, [this](rc::MissReason r) { missFilter_ = r; });
    connect(objects_, &ObjectsPanel::objectChosen, this, &MainWindow::selectObject);
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
            const int i = sceneBox_->findData(QString::fromStdString(scene_->name));
            if (i >= 0) sceneBox_->setCurrentIndex(i);
        }
        return false;
    }
    scene_ = std::move(scene);
    sceneSpec_ = spec;
    QString key = spec;
    if (QFileInfo::exists(spec)) key = QFileInfo(spec).absoluteFilePath();
    int i = sceneBox_->findData(key);
    if (i < 0) {
        sceneBox_->addItem(QFileInfo::exists(spec) ? QFileInfo(spec).fileName() : spec, key);
        i = sceneBox_->count() - 1;
    }
    sceneBox_->setCurrentIndex(i);
    objects_->setScene(scene_.get());
    selection_ = {};
    resetSession();
    return true;
}

void MainWindow::openSceneDialog() {
    const QString file = QFileDialog::getOpenFileName(this, "Open NFF scene", QString(), "NFF scenes (*.nff);;All files (*)");
    if (!file.isEmpty()) loadScene(file);
}

void MainWindow::setCache(rc::CacheKind k) {
    options_.cache = k;
    cacheBox_->setCurrentIndex(cacheBox_->findData(int(k)));
    resetSession();
}

void MainWindow::setAccel(rc::AccelKind k) {
    options_.accel = k;
    accelBox_->setCurrentIndex(accelBox_->findData(int(k)));
    resetSession();
}

int MainWindow::focusShowcase() {
    const rc::SessionState* s = controller_.state();
    if (!s) return -1;
    // The paper's Figure 2 on screen, or the newest hit (rc::showcaseEvent)
    const int best = rc::showcaseEvent(*s);
    if (best >= 0) selectEvent(best);
    return best;
}

bool MainWindow::selectRay(int x, int y, const QString& path, QString& error) {
    const rc::SessionState* s = controller_.state();
    if (!s) {
        error = "no render to select in";
        return false;
    }
    if (x < 0 || y < 0 || x >= s->width() || y >= s->height()) {
        error = QString("pixel (%1,%2) is outside the %3x%4 image").arg(x).arg(y).arg(s->width()).arg(s->height());
        return false;
    }
    selectPixel(x, y);
    if (path.isEmpty()) return true;
    std::string why;
    const int found = rc::eventAtPath(*s, y * s->width() + x, path.toStdString(), why);
    if (found < 0) {
        error = QString::fromStdString(why);
        return false;
    }
    return selectEvent(found);
}

void MainWindow::setOrder(rc::OrderKind k) {
    options_.order = k;
    orderBox_->setCurrentIndex(orderBox_->findData(int(k)));
    resetSession();
}

void MainWindow::setImageSize(int width, int height) {
    options_.width = width;
    options_.height = height;
    sizeChoice_ = -1;
    resetSession();
}

void MainWindow::resetSession() {
    if (!scene_) return;
    FrameTask task("new-session");
    setPlaying(false);
    // The image size may change: pixels selected in the old render mean nothing now
    selection_.pixel = selection_.event = -1;
    const rc::RenderOptions o = effectiveOptions();
    if (compareChoice_) compare_.clear();  // rebuilt with the new choices below
    // Built on the worker when the window is live (and on to a stop's first rays)
    if (workerSessions_) {
        controller_.resetOnWorker({scene_, o}, rc::RunGoal::ToStep, stepsOnReset_);
    } else {
        try {
            controller_.reset({scene_, o});
        } catch (const std::exception& e) {
            reportError_("Cannot start the render", QString::fromUtf8(e.what()));
        }
    }
    startCompare();
    updateControls();
}

void MainWindow::setOverlays(const Overlays& o) {
    const double lineScale = overlays_.lineScale;
    overlays_ = o;
    overlays_.lineScale = lineScale;
    const QSignalBlocker b1(cylinderBox_), b2(hullBox_), b3(frontierBox_), b4(missesBox_), b5(gridBox_), b6(legendBox_),
        b7(samplesBox_);
    samplesBox_->setChecked(o.samples);
    legendBox_->setChecked(o.legend);
    cylinderBox_->setChecked(o.cylinder);
    hullBox_->setChecked(o.hull);
    frontierBox_->setChecked(o.frontier);
    missesBox_->setChecked(o.misses);
    gridBox_->setChecked(o.grid);
    view_->setGridEnabled(o.grid);
    viewsChanged();
}

void MainWindow::setHeatmap(Heatmap h) {
    heatmap_ = h;
    overlayPainter_.setHeatmap(h, heatmapTop());
    heatmapBox_->setCurrentIndex(heatmapBox_->findData(int(h)));
    refresh();
}

void MainWindow::setPresentation(bool on) {
    if (presentAct_ && presentAct_->isChecked() != on) {
        presentAct_->setChecked(on);  // comes back here through toggled()
        return;
    }
    // Leaving brings back the panels that were shown, the tabs that were raised and the
    // fonts that were chosen
    if (on == presenting_) return;
    presenting_ = on;
    if (on) {
        shownBeforePresent_.clear();
        raisedBeforePresent_.clear();
        for (QDockWidget* d : docks_) {
            if (!d->isHidden()) shownBeforePresent_ << d;
            if (d->isVisible()) raisedBeforePresent_ << d;  // on screen: the front tab of its group
        }
        fontsBeforePresent_ = largeFonts_;
    }
    for (QDockWidget* d : docks_) d->setVisible(on ? false : shownBeforePresent_.contains(d));
    if (!on)
        for (QDockWidget* d : raisedBeforePresent_) d->raise();
    for (QToolBar* t : findChildren<QToolBar*>())
        if (t->objectName() == "render") t->setVisible(!on);
    // Presenting: larger still than large fonts (setLargeFonts reads presenting_)
    setLargeFonts(on || fontsBeforePresent_);
    view_->fit();
}

void MainWindow::showPanels(const QStringList& names) {
    for (int i = 0; i < int(docks_.size()); ++i) {
        const bool on = names.contains(panelNames()[i]);
        QDockWidget* d = docks_[std::size_t(i)];
        // Presenting: the stop's panels are what leaving presentation brings back
        if (presenting_) {
            shownBeforePresent_.removeAll(d);
            raisedBeforePresent_.removeAll(d);
            if (on) {
                shownBeforePresent_ << d;
                raisedBeforePresent_ << d;
            }
            continue;
        }
        d->setVisible(on);
        if (on) docks_[std::size_t(i)]->raise();
    }
}

void MainWindow::setLargeFonts(bool on) {
    largeFonts_ = on;
    if (largeAct_ && largeAct_->isChecked() != on) {
        const QSignalBlocker b(largeAct_);
        largeAct_->setChecked(on);
    }
    if (stats_) stats_->setLargeFonts(on);
    // Points of the text: large fonts for a projector, larger still when presenting
    constexpr double kNormalPoints = 10.0, kLargePoints = 16.0, kPresentingPoints = 20.0;
    overlays_.lineScale = presenting_ ? 2.2 : on ? 1.8 : 1.0;
    QFont f = QApplication::font();
    f.setPointSizeF(presenting_ ? kPresentingPoints : on ? kLargePoints : kNormalPoints);
    QApplication::setFont(f);
    for (QWidget* w : findChildren<QWidget*>()) w->setFont(f);
    // The toolbars' labels stay small: on a projector the boxes they name must fit a row
    QFont label = f;
    label.setPointSizeF(on ? 11.0 : 10.0);
    for (QLabel* l : findChildren<QLabel*>("toolbarLabel")) l->setFont(label);
    // Tighter buttons, so that each toolbar keeps to one row of a 1280-pixel screen
    for (QToolBar* t : findChildren<QToolBar*>())
        t->setStyleSheet(on ? "QToolButton { padding: 1px 2px; margin: 0px; }" : QString());
    view_->setFont(f);
    view_->update();
}

void MainWindow::selectPixel(int x, int y) {
    const rc::SessionState* s = controller_.state();
    if (!s || x < 0 || y < 0 || x >= s->width() || y >= s->height()) {
        selection_.pixel = -1;
    } else {
        selection_.pixel = y * s->width() + x;
        statusBar()->showMessage(QString("pixel (%1, %2)").arg(x).arg(y));
    }
    selection_.event = -1;
    rayTree_->showPixel(s, selection_.pixel);
    viewsChanged();
}

bool MainWindow::selectEvent(int event) {
    const rc::SessionState* s = controller_.state();
    if (!s || event < 0 || std::size_t(event) >= s->recorder().events().size()) return false;
    const int pixel = s->recorder().events()[std::size_t(event)].pixel;
    if (pixel != selection_.pixel) selectPixel(pixel % s->width(), pixel / s->width());
    selection_.event = event;
    rayTree_->setCurrentEvent(event);
    viewsChanged();
    return true;
}

void MainWindow::selectObject(int object) {
    selection_.object = object;
    viewsChanged();
}

void MainWindow::stepRay() { controller_.stepRay(); }
void MainWindow::stepPixel() { controller_.start(rc::RunGoal::NextPixel); }void MainWindow::runToNextMiss() {
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
    if (playAct_ && playAct_->isChecked() != on) {
        playAct_->setChecked(on);  // comes back here through toggled()
        return;
    }
    playCredit_ = 0.0;
    if (on) playTimer_.start();
    else playTimer_.stop();
    if (playAct_) playAct_->setText(on ? "Pause" : "Play");
}

void MainWindow::onPlayTick() {
    rc::SessionState* s = controller_.state();
    if (!s) return;
    const double perSecond = std::pow(10.0, speed_->value() / 25.0);
    playCredit_ += perSecond * playTimer_.interval() / 1000.0;
    int n = int(playCredit_);
    playCredit_ -= n;
    if (n == 0) return;
    bool more = true;
    while (n-- > 0 && (more = s->step())) {}
    if (!more) setPlaying(false);
    refresh();
}

int MainWindow::beamPath() const {
    if (const rc::SessionState* s = controller_.state())
        if (const auto& e = s->recorder().lastCommitted()) return e->task.node;
    return 0;
}

void MainWindow::refresh() {
    const rc::SessionState* s = controller_.state();
    if (!s) return;
    const double top = heatmapTop();
    overlayPainter_.setHeatmap(heatmap_, top);
    {
        FrameTask task("refresh-image");
        view_->setImage(HeatmapBuilder::build(*s, heatmap_, beamPath(), top));
    }
    // Panels out of sight wait until they are shown (each dock refreshes when it appears)
    if (stats_->isVisibleTo(this)) {
        FrameTask task("refresh-statistics");
        stats_->refresh(s, compareChoice_ ? compare_.state() : nullptr);
    }
    if (cacheTree_->isVisibleTo(this)) {
        FrameTask task("refresh-cache-tree");
        const auto focus = s ? rc::RayFocus::of(*s, selection_) : std::nullopt;
        cacheTree_->refresh(s, focus ? focus->node : -1);
    }
    if (eventLog_->isVisibleTo(this)) {
        FrameTask task("refresh-event-log");
        eventLog_->refresh(s);
    }
    if (rayTree_->isVisibleTo(this)) {
        FrameTask task("refresh-ray-tree");
        // The ray tree follows the selected pixel, else the pixel being traced
        int pixel = selection_.pixel;
        if (pixel < 0 && s->recorder().lastEvent()) pixel = s->recorder().lastEvent()->task.pixel;
        rayTree_->showPixel(s, pixel);
        if (const auto f = rc::RayFocus::of(*s, selection_)) rayTree_->setCurrentEvent(f->event);
    }
    statusBar()->showMessage(QString("%1 steps%2").arg(s->session().steps()).arg(s->session().done() ? ", done" : "") +
                             QString::fromStdString(rc::cannotDrawYet().empty() ? "" : " — " + rc::cannotDrawYet()));
    updateControls();
    if (compareChoice_) refreshCompare();
    viewsChanged();
}

void MainWindow::onBusyChanged(bool busy) {
    progress_->setVisible(busy);
    progressCancel_->setVisible(busy);
    if (busy) progress_->setValue(0);
    if (busy) {
        // The worker owns the state now: let go of every view of it
        eventLog_->refresh(nullptr);
        rayTree_->showPixel(nullptr, -1);
    }
    updateControls();
    view_->update();
}

void MainWindow::updateControls() {
    const bool busy = controller_.busy();
    const rc::SessionState* s = controller_.state();
    const bool canStep = !busy && s && !s->session().done();
    for (QAction* a : {stepRayAct_, stepPixelAct_, nextMissAct_, nextDeferralAct_, runAct_}) if (a) a->setEnabled(canStep);
    if (goToAct_) goToAct_->setEnabled(!busy && s);
    if (playAct_) playAct_->setEnabled(canStep || playTimer_.isActive());
    if (backAct_) backAct_->setEnabled(!busy && s && s->session().steps() > 0);
    if (cancelAct_) cancelAct_->setEnabled(busy);
    for (QWidget* w : std::initializer_list<QWidget*>{sceneBox_, cacheBox_, orderBox_, accelBox_, sizeBox_, compareBox_}) if (w) w->setEnabled(!busy);
    if (resetAct_) resetAct_->setEnabled(true);
    if (openAct_) openAct_->setEnabled(!busy);
    // Hide the overlays this cache and order cannot draw: no cache has no cylinder, hull or
    // misses; only the blocker caches have hulls; only breadth-first order has a frontier
    if (s) {
        const rc::RenderOptions& o = s->session().options();
        const bool cached = o.cache != rc::CacheKind::None;
        if (cylinderAct_) cylinderAct_->setVisible(cached);
        if (missesAct_) missesAct_->setVisible(cached);
        if (hullAct_) hullAct_->setVisible(s->session().strategy().blockerLists() != nullptr);
        if (frontierAct_) frontierAct_->setVisible(o.order == rc::OrderKind::BreadthFirst);
    }
}

QStringList MainWindow::sceneChoices() const {
    QStringList out;
    for (int i = 0; i < sceneBox_->count(); ++i) out << sceneBox_->itemText(i);
    return out;
}

QStringList MainWindow::cacheChoices() const {
    QStringList out;
    for (int i = 0; i < cacheBox_->count(); ++i) out << cacheBox_->itemText(i);
    return out;
}

QString MainWindow::cacheShown() const { return cacheBox_->currentText(); }

QStringList MainWindow::offeredOverlays() const {
    QStringList out;
    for (QAction* a : {cylinderAct_, hullAct_, frontierAct_, missesAct_})
        if (a && a->isVisible()) out << qobject_cast<QCheckBox*>(qobject_cast<QWidgetAction*>(a)->defaultWidget())->text();
    return out;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    setPlaying(false);
    controller_.cancel();
    compare_.cancel();
    controller_.wait();
    compare_.wait();
    e->accept();
}

// [apply-stop]
bool MainWindow::apply(const GuiOptions& o, bool wait) {
    FrameTask task("apply");
    // Whatever runs gives way to the new state
    pending_.reset();
    setPlaying(false);
    for (SessionController* c : {&controller_, &compare_}) {
        c->cancel();
        c->wait();
    }
    // Choose everything first, then build one session with these choices
    setOverlays(o.overlays);
    options_.cache = o.cache;
    options_.order = o.order;
    options_.accel = o.accel;
    options_.band = o.band;
    options_.shading.sampling = o.sampling;
    options_.width = std::max(0, o.width);
    options_.height = std::max(0, o.height);
    sizeChoice_ = o.width > 0 || o.height > 0 ? -1 : 0;
    cacheBox_->setCurrentIndex(cacheBox_->findData(int(o.cache)));
    orderBox_->setCurrentIndex(orderBox_->findData(int(o.order)));
    accelBox_->setCurrentIndex(accelBox_->findData(int(o.accel)));
    sizeBox_->setCurrentIndex(sizeChoice_ == 0 ? 0 : sizeBox_->findData(std::max(o.width, o.height)));
    compareChoice_ = o.compare;
    compareView_->setVisible(o.compare.has_value());
    if (!o.compare) {
        compare_.clear();
        comparePainter_.setExtraCaption({});
    }
    compareBox_->setCurrentIndex(std::max(0, o.compare ? compareBox_->findData(toString(*o.compare)) : 0));
    setMissFilter(o.missReason);
    if (o.panels) showPanels(*o.panels);
    selection_ = {};
    // A live window builds the render on the worker, which goes on to the stop's rays
    const bool onWorker = workerSessions_ && !wait;
    stepsOnReset_ = onWorker ? std::max<std::int64_t>(0, o.steps) : 0;
    const bool loaded = (scene_ && o.scene == sceneSpec_) ? (resetSession(), true) : loadScene(o.scene);
    stepsOnReset_ = 0;
    if (!loaded) return false;
    if (onWorker) {
        pending_ = o;
        pendingRun_ = false;
        return true;
    }
    // The stop's rays, and on to the miss or deferral it shows: here when asked to wait,
    // else on the worker (the window stays live)
    if (rc::SessionState* s = controller_.state()) s->setMissFilter(missFilter_);
    if (!wait && (o.steps > 0 || o.runTo)) {
        pending_ = o;
        pendingRun_ = false;
        if (o.steps > 0) controller_.goToStep(o.steps);
        else continuePending();
        return true;
    }
    if (rc::SessionState* s = controller_.state()) {
        if (o.steps > 0) s->runUntil(rc::RunGoal::ToStep, o.steps);
        if (o.runTo) s->runUntil(*o.runTo, 0);
    }
    return finishApply(o, wait);
}

void MainWindow::continuePending() {
    if (pending_->runTo && !pendingRun_) {
        pendingRun_ = true;
        if (rc::SessionState* s = controller_.state()) s->setMissFilter(missFilter_);
        if (controller_.start(*pending_->runTo)) return;
    }
    const GuiOptions o = *pending_;
    pending_.reset();
    finishApply(o, false);
}

bool MainWindow::finishApply(const GuiOptions& o, bool wait) {
    if (compareChoice_) syncCompare(wait);
    setHeatmap(o.heatmap);
    setSceneView(o.sceneView);
    if (o.sceneView) {
        sceneView_->setAngle(o.sceneAngle);
        sceneView_->setOrbit(o.orbitYaw, o.orbitPitch);
    }
    refresh();
    // The miss or deferral run to; else, the scene view with nothing selected: a ray worth
    // seeing from the side
    const rc::SessionState* s = controller_.state();
    if (o.runTo && s && s->stopEvent() >= 0) selectEvent(s->stopEvent());
    else if (o.firstImpression || (o.sceneView && o.select.x() < 0)) focusShowcase();
    if (o.select.x() >= 0) {
        QString why;
        if (!selectRay(o.select.x(), o.select.y(), o.selectPath, why)) {
            reportError_("Cannot select", "--select: " + why);
            return false;
        }
    }
    frameViews(o);
    emit shown();
    return true;
}
// [apply-stop]

void MainWindow::frameViews(const GuiOptions& o) {
    // The compared view follows the first's zoom and pan from here on
    if (compareChoice_) compareView_->fit();
    if (!o.focus.isEmpty()) {
        view_->fitRect(QRectF(o.focus));
    } else if (o.zoom != 1.0) {
        // Zoom about the selected pixel, else the pixel of the ray being traced
        view_->fit();
        QPointF centre(view_->image().width() / 2.0, view_->image().height() / 2.0);
        const rc::SessionState* s = controller_.state();
        int pixel = selection_.pixel;
        if (pixel < 0 && s && s->recorder().lastEvent()) pixel = s->recorder().lastEvent()->task.pixel;
        if (s && pixel >= 0) centre = QPointF(pixel % s->width() + 0.5, pixel / s->width() + 0.5);
        // The rectangle that, fitted, is `o.zoom` times the whole image's fit
        const double z = o.zoom * view_->zoom();
        const QSizeF seen(view_->width() / z, view_->height() / z);
        view_->fitRect(QRectF(centre - QPointF(seen.width(), seen.height()) / 2.0, seen));
    } else {
        view_->fit();
    }
}

void MainWindow::buildTourBar() {
    // Its own row at the top: where the lecture is, and the way on
    addToolBarBreak(Qt::TopToolBarArea);
    tourBar_ = new QToolBar("Tour", this);
    tourBar_->setObjectName("tour");
    addToolBar(Qt::TopToolBarArea, tourBar_);
    QAction* back = tourBar_->addAction("◀ Stop", this, &MainWindow::previousStop);
    back->setShortcuts({QKeySequence(Qt::Key_PageUp)});
    back->setShortcutContext(Qt::ApplicationShortcut);
    back->setToolTip("The previous stop (PageUp, as a presenter's clicker sends)");
    stopBox_ = new QComboBox(this);
    stopBox_->setFocusPolicy(Qt::NoFocus);
    stopBox_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    stopBox_->setToolTip("The tour's stops: choose one to go there");
    tourBar_->addWidget(stopBox_);
    connect(stopBox_, &QComboBox::activated, this, [this](int i) { goToStop(i + 1); });
    QAction* next = tourBar_->addAction("Stop ▶", this, &MainWindow::nextStop);
    next->setShortcuts({QKeySequence(Qt::Key_PageDown)});
    next->setShortcutContext(Qt::ApplicationShortcut);
    next->setToolTip("The next stop (PageDown, as a presenter's clicker sends)");
    QAction* again = tourBar_->addAction("As written", this, &MainWindow::restoreStop);
    again->setShortcut(Qt::Key_R);
    again->setToolTip("Back to this stop as the tour wrote it, after stepping, selecting or toggling (R)");
    tourBar_->hide();
}

void MainWindow::setTour(const rc::Tour& tour, std::vector<GuiOptions> stops) {
    tour_ = tour;
    stops_ = std::move(stops);
    stop_ = 0;
    const QSignalBlocker b(stopBox_);
    stopBox_->clear();
    for (std::size_t i = 0; i < tour_.stops.size(); ++i)
        stopBox_->addItem(QString("%1/%2  %3").arg(i + 1).arg(tour_.stops.size()).arg(QString::fromStdString(tour_.stops[i].title)));
    tourBar_->setVisible(!stops_.empty());
    if (!tour_.title.empty()) setWindowTitle(QString::fromStdString(tour_.title) + " — RayCache");
}

bool MainWindow::goToStop(int stop, bool wait) {
    if (stop < 1 || stop > stopCount()) return false;
    FrameTask task(QString("stop-%1").arg(stop));
    stop_ = stop;
    {
        const QSignalBlocker b(stopBox_);
        stopBox_->setCurrentIndex(stop - 1);
    }
    const rc::TourStop& st = tour_.stops[std::size_t(stop - 1)];
    tourCaption_->setText(QString("<b>%1/%2 &nbsp;%3.</b> %4")
                              .arg(stop).arg(stopCount())
                              .arg(QString::fromStdString(st.title).toHtmlEscaped(),
                                   QString::fromStdString(st.caption).toHtmlEscaped()));
    tourCaption_->show();
    return apply(stops_[std::size_t(stop - 1)], wait);
}

QString MainWindow::tourCaption() const { return tourCaption_->isVisible() || stop_ > 0 ? tourCaption_->text() : QString(); }

void MainWindow::setWorkerSessions(bool on) {
    workerSessions_ = on;
    stats_->setThrottled(on);
    // A long event log is read into the per-pixel layers over several paints (a
    // screenshot reads it all at once)
    const std::size_t budget = on ? kLayerEventsPerPaint : 0;
    overlayPainter_.setEventBudget(budget, [this] { QTimer::singleShot(0, view_, [this] { view_->update(); }); });
    comparePainter_.setEventBudget(budget, [this] { QTimer::singleShot(0, compareView_, [this] { compareView_->update(); }); });
}

void MainWindow::setMissFilter(rc::MissReason r) {
    missFilter_ = r;
    eventLog_->setReason(r);
}

}  // namespace rcgui
