#include "toolbars.h"

#include <cmath>
#include <limits>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QInputDialog>
#include <QLabel>
#include <QSlider>
#include <QToolBar>
#include <QWidgetAction>

#include "image_view.h"
#include "labels.h"
#include "main_window.h"
#include "order/order_registry.h"
#include "search/search_registry.h"
#include "view/scene_list.h"

namespace rcgui {

namespace {
// Play's speed slider: 0-100, rays per second 10^(value / 25), from 1 to 10,000
constexpr int kSpeedSteps = 100, kSpeedStart = 40;
constexpr double kSpeedStepsPerDecade = 25.0;
constexpr int kSpeedSliderWidth = 160;
// The image sizes the Size box offers (the longer side), beside the scene's own
constexpr int kSizes[] = {32, 64, 128, 256, 512, 1024};
// Boxes whose entries are long show this many characters, and scroll the rest
constexpr int kSceneBoxCharacters = 10, kCompareBoxCharacters = 12;
}  // namespace

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

Toolbars::Toolbars(MainWindow& window) : QObject(&window), w_(window) {
    buildRender();
    window.addToolBarBreak();
    buildStep();
    // What to show: a row of its own, so that nothing spills into an overflow menu
    window.addToolBarBreak();
    buildShow();
}

QLabel* Toolbars::label(const QString& text) {
    auto* l = new QLabel(" " + text + " ", &w_);
    l->setObjectName("toolbarLabel");
    return l;
}

QComboBox* Toolbars::box(QToolBar* bar, const QString& name) {
    auto* b = new QComboBox(&w_);
    b->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    bar->addWidget(label(name));
    bar->addWidget(b);
    return b;
}

void Toolbars::buildRender() {
    // Scene and render choices
    QToolBar* render = w_.addToolBar("Render");
    render->setObjectName("render");
    buildSceneAndCache(render);
    buildChoices(render);
    resetAct_ = render->addAction("Reset", &w_, &MainWindow::resetSession);
}

void Toolbars::buildSceneAndCache(QToolBar* bar) {
    scene_ = box(bar, "Scene");
    scene_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    scene_->setMinimumContentsLength(kSceneBoxCharacters);
    // Built-ins (cube:N and balls:N in the sizes the core suggests), then every scene of the
    // project's scenes/ folder: the core's list (rc::sceneChoices), as the page's
    for (const rc::SceneChoice& c : rc::sceneChoices(QDir(scenesFolder()).absolutePath().toStdString())) {
        scene_->addItem(QString::fromStdString(c.label), QString::fromStdString(c.spec));
        scene_->setItemData(scene_->count() - 1, QString::fromStdString(c.description), Qt::ToolTipRole);
    }
    scene_->setToolTip("Scene: built-ins, or files opened with Open…");
    openAct_ = bar->addAction("Open…", &w_, &MainWindow::openSceneDialog);
    openAct_->setShortcut(QKeySequence::Open);
    connect(scene_, &QComboBox::activated, &w_, [this](int i) { w_.loadScene(scene_->itemData(i).toString()); });

    // The cache: every cache, RayCache's blocker+ and blocker+dir beside the paper's two
    cache_ = box(bar, "Cache");
    for (auto k : rc::allCacheKinds()) cache_->addItem(text(rc::toString(k)), int(k));
    cache_->setCurrentIndex(cache_->findData(int(rc::CacheKind::Blocker)));
    connect(cache_, &QComboBox::activated, &w_, [this](int i) { w_.setCache(rc::CacheKind(cache_->itemData(i).toInt())); });
}

void Toolbars::buildChoices(QToolBar* bar) {
    // The order: every registered order
    order_ = box(bar, "Order");
    for (std::size_t k = 0; k < rc::orderRegistry().size(); ++k) order_->addItem(text(rc::orderRegistry()[k].name), int(k));
    order_->setCurrentIndex(order_->findData(int(rc::OrderKind::BreadthFirst)));
    order_->setToolTip("progressive: all eye rays first, then deeper rays (the paper's conclusion)");
    connect(order_, &QComboBox::activated, &w_, [this](int i) { w_.setOrder(rc::OrderKind(order_->itemData(i).toInt())); });
    // The complete search: every exact one
    accel_ = box(bar, "Search");
    for (std::size_t k = 0; k < rc::searchRegistry().size(); ++k)
        if (!rc::searchRegistry()[k].comparisonOnly) accel_->addItem(text(rc::searchRegistry()[k].name), int(k));
    accel_->setToolTip("What answers the complete searches: a linear scan, a uniform grid or a BVH");
    connect(accel_, &QComboBox::activated, &w_, [this](int i) { w_.setAccel(rc::AccelKind(accel_->itemData(i).toInt())); });
    // The image size
    size_ = box(bar, "Size");
    size_->addItem("scene's", 0);
    for (int n : kSizes) size_->addItem(QString::number(n), n);
    connect(size_, &QComboBox::activated, &w_, [this](int i) { w_.setSizeChoice(size_->itemData(i).toInt()); });
    // A second render to compare with
    compare_ = box(bar, "Compare");
    compare_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    compare_->setMinimumContentsLength(kCompareBoxCharacters);
    compare_->addItem("off", "off");
    for (auto c : rc::allCacheKinds())
        for (auto o : rc::allOrderKinds()) compare_->addItem(toString(CompareChoice{c, o}), toString(CompareChoice{c, o}));
    compare_->setToolTip("Compare: run a second render with another cache and order beside this one, in lockstep");
    connect(compare_, &QComboBox::activated, &w_, [this](int i) {
        QString why;
        if (!w_.setCompare(compare_->itemData(i).toString(), why)) w_.reportError("Cannot compare", why);
    });
}

void Toolbars::buildStep() {
    QToolBar* step = w_.addToolBar("Step");
    step->setObjectName("step");
    // Step a ray, a pixel, to the next miss or deferral, to a step, back
    stepRayAct_ = step->addAction("Step ray", &w_, &MainWindow::stepRay);
    stepRayAct_->setShortcut(Qt::Key_Space);
    stepRayAct_->setToolTip("Trace exactly one ray (Space)");
    stepPixelAct_ = step->addAction("Step pixel", &w_, &MainWindow::stepPixel);
    stepPixelAct_->setToolTip("Trace until a ray of another pixel is traced");
    nextMissAct_ = step->addAction("Next miss", &w_, &MainWindow::runToNextMiss);
    nextMissAct_->setShortcut(Qt::Key_M);
    nextMissAct_->setToolTip("Trace until a cache miss (of the reason the event log chooses), and focus on it (M)");
    nextDeferralAct_ = step->addAction("Next deferral", &w_, &MainWindow::runToNextDeferral);
    nextDeferralAct_->setShortcut(Qt::Key_D);
    nextDeferralAct_->setToolTip("Trace until a ray is deferred (its cheap test failed), and focus on it (D)");
    goToAct_ = step->addAction("Go to step…", &w_, [this] {
        const rc::SessionState* s = w_.controller().state();
        if (!s) return;
        bool ok = false;
        const qint64 n = QInputDialog::getInt(&w_, "Go to step", "Step:", int(s->session().steps()), 0,
                                              std::numeric_limits<int>::max(), 1, &ok);
        if (ok) w_.goToStep(n);
    });
    goToAct_->setShortcut(Qt::CTRL | Qt::Key_G);
    backAct_ = step->addAction("Step back", &w_, &MainWindow::stepBack);
    backAct_->setShortcut(Qt::Key_Backspace);
    backAct_->setToolTip("Rebuild and replay to one step before (the core is deterministic)");
    buildPlay(step);
    cancelAct_ = step->addAction("Cancel", &w_, &MainWindow::cancelRun);
    cancelAct_->setShortcut(Qt::Key_Escape);
}

void Toolbars::buildPlay(QToolBar* bar) {
    // Play at a speed, run to the end
    playAct_ = bar->addAction("Play");
    playAct_->setCheckable(true);
    connect(playAct_, &QAction::toggled, &w_, &MainWindow::setPlaying);
    speed_ = new QSlider(Qt::Horizontal, &w_);
    speed_->setRange(0, kSpeedSteps);
    speed_->setValue(kSpeedStart);
    speed_->setMaximumWidth(kSpeedSliderWidth);
    speedLabel_ = new QLabel(&w_);
    auto showSpeed = [this] { speedLabel_->setText(QString(" %1 rays/s ").arg(std::round(raysPerSecond()))); };
    showSpeed();
    connect(speed_, &QSlider::valueChanged, this, showSpeed);
    bar->addWidget(speed_);
    bar->addWidget(speedLabel_);
    runAct_ = bar->addAction("Run to end", &w_, &MainWindow::runToEnd);
}

double Toolbars::raysPerSecond() const { return std::pow(10.0, speed_->value() / kSpeedStepsPerDecade); }

QCheckBox* Toolbars::overlayBox(QToolBar* bar, const QString& label, const QString& tip, bool Overlays::*field) {
    auto* c = new QCheckBox(label, &w_);
    c->setToolTip(tip);
    c->setChecked(w_.overlays().*field);
    connect(c, &QCheckBox::toggled, &w_, [this, field](bool on) {
        Overlays o = w_.overlays();
        o.*field = on;
        w_.setOverlays(o);
    });
    bar->addWidget(c);
    return c;
}

void Toolbars::buildShow() {
    QToolBar* show = w_.addToolBar("Show");
    show->setObjectName("show");
    // The overlays, a check box each
    cylinderBox_ = overlayBox(show, "Cylinder", "Cylinder of safety of the active cache entry", &Overlays::cylinder);
    hullBox_ = overlayBox(show, "Hull", "Blocker hull of origin and target, its blockers (orange) and target (green)", &Overlays::hull);
    frontierBox_ = overlayBox(show, "Frontier", "Breadth-first queue, deferred seeds and regions", &Overlays::frontier);
    missesBox_ = overlayBox(show, "Misses", "Where misses happened, coloured by reason", &Overlays::misses);
    samplesBox_ = overlayBox(show, "Samples",
                             "The sample rays of the pixel in focus: its eye samples, the shadow rays of each hit "
                             "fanning to the light's sphere (reaching it or blocked), its glossy reflections",
                             &Overlays::samples);
    gridBox_ = overlayBox(show, "Grid", "Pixel grid at high zoom", &Overlays::grid);
    legendBox_ = overlayBox(show, "Legend", "The colour key (beside the image when there is room)", &Overlays::legend);
    const QList<QAction*> shown = show->actions();
    cylinderAct_ = shown.value(0);
    hullAct_ = shown.value(1);
    frontierAct_ = shown.value(2);
    missesAct_ = shown.value(3);
    // The heatmap in place of the image
    heatmap_ = new QComboBox(&w_);
    heatmap_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    heatmap_->addItem("image", int(Heatmap::None));
    heatmap_->addItem("tests per pixel", int(Heatmap::Tests));
    heatmap_->addItem("hits / misses", int(Heatmap::HitMiss));
    heatmap_->addItem("cache hit rate", int(Heatmap::HitRate));
    heatmap_->addItem("visiting order", int(Heatmap::VisitOrder));
    heatmap_->addItem("beam-tree node", int(Heatmap::BeamNode));
    show->addWidget(label("Show"));
    show->addWidget(heatmap_);
    connect(heatmap_, &QComboBox::activated, &w_, [this](int i) { w_.setHeatmap(Heatmap(heatmap_->itemData(i).toInt())); });
    buildViewActions(show);
}

void Toolbars::buildViewActions(QToolBar* bar) {
    // Fonts, presentation, the scene view, fit
    largeAct_ = bar->addAction("Large fonts");
    largeAct_->setCheckable(true);
    largeAct_->setToolTip("Bigger text for a projector");
    connect(largeAct_, &QAction::toggled, &w_, &MainWindow::setLargeFonts);
    presentAct_ = bar->addAction("Present");
    presentAct_->setCheckable(true);
    presentAct_->setShortcut(Qt::Key_F11);
    presentAct_->setToolTip("Presentation mode: hide the panels, large fonts (F11)");
    connect(presentAct_, &QAction::toggled, &w_, &MainWindow::setPresentation);
    sceneViewAct_ = bar->addAction("Scene view");
    sceneViewAct_->setCheckable(true);
    sceneViewAct_->setToolTip("Show the 3D scene from the side: objects, lights, the ray tree in focus, its cylinder and hull");
    connect(sceneViewAct_, &QAction::toggled, &w_, &MainWindow::setSceneView);
    QAction* fit = bar->addAction("Fit", w_.imageView(), &ImageView::fit);
    fit->setToolTip("Fit the image to the window (F)");
}

void Toolbars::showOverlays(const Overlays& o) {
    const QSignalBlocker b1(cylinderBox_), b2(hullBox_), b3(frontierBox_), b4(missesBox_), b5(gridBox_), b6(legendBox_),
        b7(samplesBox_);
    samplesBox_->setChecked(o.samples);
    legendBox_->setChecked(o.legend);
    cylinderBox_->setChecked(o.cylinder);
    hullBox_->setChecked(o.hull);
    frontierBox_->setChecked(o.frontier);
    missesBox_->setChecked(o.misses);
    gridBox_->setChecked(o.grid);
}

void Toolbars::showChoices(const rc::RenderOptions& o, int sizeChoice) {
    cache_->setCurrentIndex(cache_->findData(int(o.cache)));
    order_->setCurrentIndex(order_->findData(int(o.order)));
    accel_->setCurrentIndex(accel_->findData(int(o.accel)));
    if (sizeChoice >= 0) size_->setCurrentIndex(std::max(0, size_->findData(sizeChoice)));
    else size_->setCurrentIndex(size_->findData(std::max(o.width, o.height)));
}

void Toolbars::showHeatmap(Heatmap h) { heatmap_->setCurrentIndex(heatmap_->findData(int(h))); }

void Toolbars::showSceneView(bool on) {
    if (sceneViewAct_->isChecked() == on) return;
    const QSignalBlocker b(sceneViewAct_);
    sceneViewAct_->setChecked(on);
}

bool Toolbars::showPlaying(bool on) {
    if (playAct_->isChecked() != on) {
        playAct_->setChecked(on);  // comes back to the window's setPlaying() through toggled()
        return true;
    }
    playAct_->setText(on ? "Pause" : "Play");
    return false;
}

void Toolbars::update(bool busy, const rc::SessionState* s, bool playing) {
    const bool canStep = !busy && s && !s->session().done();
    for (QAction* a : {stepRayAct_, stepPixelAct_, nextMissAct_, nextDeferralAct_, runAct_}) a->setEnabled(canStep);
    goToAct_->setEnabled(!busy && s);
    playAct_->setEnabled(canStep || playing);
    backAct_->setEnabled(!busy && s && s->session().steps() > 0);
    cancelAct_->setEnabled(busy);
    for (QWidget* w : std::initializer_list<QWidget*>{scene_, cache_, order_, accel_, size_, compare_}) w->setEnabled(!busy);
    resetAct_->setEnabled(true);
    openAct_->setEnabled(!busy);
    // Hide the overlays this cache and order cannot draw: no cache has no cylinder, hull or
    // misses; only the blocker caches have hulls; only breadth-first order has a frontier
    if (!s) return;
    const rc::RenderOptions& o = s->session().options();
    const bool cached = o.cache != rc::CacheKind::None;
    cylinderAct_->setVisible(cached);
    missesAct_->setVisible(cached);
    hullAct_->setVisible(s->session().strategy().blockerLists() != nullptr);
    frontierAct_->setVisible(o.order == rc::OrderKind::BreadthFirst);
}

namespace {
QStringList entries(const QComboBox* box) {
    QStringList out;
    for (int i = 0; i < box->count(); ++i) out << box->itemText(i);
    return out;
}
}  // namespace

QStringList Toolbars::sceneChoices() const { return entries(scene_); }
QStringList Toolbars::cacheChoices() const { return entries(cache_); }
QString Toolbars::cacheShown() const { return cache_->currentText(); }

QStringList Toolbars::offeredOverlays() const {
    QStringList out;
    for (QAction* a : {cylinderAct_, hullAct_, frontierAct_, missesAct_})
        if (a->isVisible()) out << qobject_cast<QCheckBox*>(qobject_cast<QWidgetAction*>(a)->defaultWidget())->text();
    return out;
}

}  // namespace rcgui
