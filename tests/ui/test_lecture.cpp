// GUI tests of the live lecture: tours and their stops, the keys a presenter uses, the
// overlays that scale with the screen (not with a list's length), the cause of a miss,
// the event log's reason filter and the frame log.
#include <catch2/catch.hpp>

#include <memory>

#include <QAction>
#include <QDir>
#include <QFile>
#include <QMouseEvent>
#include <QProcess>
#include <QRegularExpression>
#include <QScreen>
#include <QTemporaryDir>
#include <QTextStream>

#include "event_log_model.h"
#include "event_log_panel.h"
#include "gui_options.h"
#include "image_view.h"
#include "main_window.h"
#include "overlay_painter.h"
#include "ray_tree_panel.h"
#include "scene/builtin_scenes.h"
#include "stats_panel.h"
#include "view/miss_cause.h"
#include "view/ray_focus.h"
#include "view/tour.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::stateOf;
using rcgui::testing::stopOptionsOf;
using rcgui::testing::toursFolder;

namespace {

/// A render of the built-in `pair` with blocker lists, `size` pixels square.
rc::SessionState pairState(rc::OrderKind order, int size) {
    rc::RenderOptions ro;
    ro.cache = rc::CacheKind::Blocker;
    ro.order = order;
    ro.width = ro.height = size;
    return rc::SessionState({std::make_shared<const rc::Scene>(rc::loadScene("pair")), ro});
}

/// The window's action with shortcut `key`.
QAction* actionFor(MainWindow& w, const QKeySequence& key) {
    for (QAction* a : w.findChildren<QAction*>())
        if (a->shortcuts().contains(key)) return a;
    return nullptr;
}

}  // namespace

TEST_CASE("Every stop of the shipped tours reads as the window's options", "[gui][tour]") {
    const QStringList files = QDir(toursFolder()).entryList({"*.json"}, QDir::Files);
    REQUIRE(files.contains("hanrahan86.json"));
    REQUIRE(files.contains("debugging.json"));
    for (const QString& file : files) {
        const rc::Tour tour = rc::loadTour(QDir(toursFolder()).filePath(file).toStdString());
        const std::vector<GuiOptions> stops = stopOptionsOf(tour);
        INFO(file.toStdString());
        REQUIRE(stops.size() == tour.stops.size());
        for (std::size_t i = 0; i < stops.size(); ++i) {
            // A stop says what it shows: a scene, its rays, and its panels (none unless named)
            REQUIRE(stops[i].scene == QString::fromStdString(tour.stops[i].value("scene")));
            REQUIRE(stops[i].panels.has_value());
            // Captions are one to three sentences
            const int sentences = int(QString::fromStdString(tour.stops[i].caption).count(QRegularExpression("[.!?](\"|\\))?( |$)")));
            REQUIRE(sentences >= 1);
            REQUIRE(sentences <= 4);  // one may end in a quotation
        }
    }
    const rc::Tour paper = rc::loadTour(QDir(toursFolder()).filePath("hanrahan86.json").toStdString());
    REQUIRE(paper.stops.size() >= 12);
}

TEST_CASE("A bad stop is reported at its place in the tour file", "[gui][tour]") {
    const rc::Tour tour = rc::parseTour(R"({"stops": [
  {"title": "Fine", "caption": "c.", "scene": "pair"},
  {"title": "Bad", "caption": "c.", "scene": "pair", "cache": "lru"}]})",
                                        "t.json");
    QString why;
    REQUIRE(stopOptions(tour, 1, GuiOptions{}, why));
    REQUIRE_FALSE(stopOptions(tour, 2, GuiOptions{}, why));
    REQUIRE(why.startsWith("t.json:3:3: stop 2 (Bad): --cache"));  // the CLI's words (CLI11)
    REQUIRE(why.contains("lru"));
}

TEST_CASE("PageDown and PageUp move between stops, R brings a stop back as written", "[gui][tour]") {
    const rc::Tour tour = rc::parseTour(R"({"title": "Two", "stops": [
  {"title": "One", "caption": "First.", "scene": "pair", "cache": "cylinder", "order": "scanline", "steps": 300,
   "overlays": ["cylinder"]},
  {"title": "Two", "caption": "Second.", "scene": "trio", "cache": "blocker", "order": "bfs", "steps": 500,
   "overlays": ["cone", "frontier"], "heatmap": "tests", "panels": ["statistics"]}]})",
                                        "two.json");
    MainWindow w;
    showAt(w, 1280, 720);
    w.setTour(tour, stopOptionsOf(tour));
    REQUIRE(w.goToStop(1, true));
    REQUIRE(w.stop() == 1);
    REQUIRE(stateOf(w).session().steps() == 300);
    REQUIRE(w.overlays().cylinder);
    REQUIRE(w.tourCaption().contains("First."));
    QAction* next = actionFor(w, QKeySequence(Qt::Key_PageDown));
    QAction* back = actionFor(w, QKeySequence(Qt::Key_PageUp));
    QAction* again = actionFor(w, QKeySequence(Qt::Key_R));
    REQUIRE(next);
    REQUIRE(back);
    REQUIRE(again);
    // The next stop's rays are traced on the worker: the window stays live meanwhile
    next->trigger();
    REQUIRE(w.stop() == 2);
    w.controller().wait();
    QApplication::processEvents();
    REQUIRE(stateOf(w).session().steps() == 500);
    REQUIRE(w.scene()->name == "trio");
    REQUIRE(w.overlays().hull);
    REQUIRE_FALSE(w.overlays().cylinder);
    REQUIRE(w.statsPanel()->isVisibleTo(&w));
    REQUIRE_FALSE(w.rayTreePanel()->isVisibleTo(&w));
    REQUIRE(w.tourCaption().contains("2/2"));
    // Live: step and toggle from the stop, then R returns to it
    w.stepRay();
    w.setOverlays(*Overlays::parse("none"));
    REQUIRE(stateOf(w).session().steps() == 501);
    again->trigger();
    w.controller().wait();
    QApplication::processEvents();
    REQUIRE(stateOf(w).session().steps() == 500);
    REQUIRE(w.overlays().hull);
    // PageDown at the last stop stays; PageUp goes back
    next->trigger();
    REQUIRE(w.stop() == 2);
    back->trigger();
    w.controller().wait();
    QApplication::processEvents();
    REQUIRE(w.stop() == 1);
    REQUIRE(w.scene()->name == "pair");
    REQUIRE(stateOf(w).session().options().cache == rc::CacheKind::Cylinder);
}

TEST_CASE("The window never asks for more than the screen, and large fonts outlive present mode", "[gui][tour]") {
    MainWindow w;
    const QSize screen = QGuiApplication::primaryScreen()->availableGeometry().size();
    REQUIRE(w.width() <= screen.width());
    REQUIRE(w.height() <= screen.height());
    w.setLargeFonts(true);
    const double large = w.imageView()->font().pointSizeF();
    REQUIRE(large > 12.0);
    w.setPresentation(true);
    REQUIRE_FALSE(w.statsPanel()->isVisibleTo(&w));
    w.setPresentation(false);
    REQUIRE(w.imageView()->font().pointSizeF() == large);
    REQUIRE(w.statsPanel()->isVisibleTo(&w));
}

TEST_CASE("A hull whose list holds the whole scene draws its nearest blockers and counts the rest", "[gui][tour][stall]") {
    // SPD's sphereflake: the paper's blocker bounds the ground square by a sphere holding
    // every ball, so a shadow ray from the ground lists the whole scene
    GuiOptions o;
    QString why;
    REQUIRE(parseGuiOptions({"raycache-gui", "balls:3", "--width", "48", "--height", "48", "--cache", "blocker",
                             "--order", "scanline", "--steps", "100000", "--select", "24,45:eye/shadow 1", "--overlays",
                             "cone"},
                            o, why) == ParseResult::Ok);
    MainWindow w;
    showAt(w, 1280, 720);
    REQUIRE(w.apply(o, true));
    const auto focus = rc::RayFocus::of(stateOf(w), w.selection());
    REQUIRE(focus);
    const rc::FocusHull h = rc::hullOf(stateOf(w), *focus);
    REQUIRE(h.listed > 2 * rc::FocusHull::kShown);
    REQUIRE(h.blockers.size() == rc::FocusHull::kShown);
    w.imageView()->grab();
    // Outlines: the hull, its origin, the target and the blockers kept, nothing per listed entry
    REQUIRE(w.overlayPainter().lastWork().outlines <= int(rc::FocusHull::kShown) + 4);
    REQUIRE(w.overlayPainter().lastWork().outlines >= int(rc::FocusHull::kShown));
}

TEST_CASE("After a miss the overlay knows its cause", "[gui][tour][miss]") {
    // cube:4 at 256x256, cylinder cache, scanline: the first eye ray to leave its cylinder
    // while hitting the same sphere as the eye ray before it
    GuiOptions o;
    QString why;
    REQUIRE(parseGuiOptions({"raycache-gui", "cube:4", "--width", "64", "--height", "64", "--cache", "cylinder",
                             "--order", "scanline", "--steps", "200", "--run", "next-miss", "--miss-reason",
                             "left_cylinder", "--overlays", "cylinder"},
                            o, why) == ParseResult::Ok);
    MainWindow w;
    showAt(w, 1000, 700);
    REQUIRE(w.apply(o, true));
    const rc::SessionState& s = stateOf(w);
    const auto focus = rc::RayFocus::of(s, w.selection());
    REQUIRE(focus);
    REQUIRE(focus->decision == rc::Decision::Miss);
    REQUIRE(focus->reason == rc::MissReason::LeftCylinder);
    const rc::MissCause c = rc::missCauseOf(s, *focus);
    REQUIRE(c.valid());
    // The cached ray is the last one at the same path, and the cylinder it left is real
    const rc::EventRecord& cached = s.recorder().events()[std::size_t(c.cachedEvent)];
    REQUIRE(cached.node == focus->node);
    REQUIRE(c.cachedEvent < focus->event);
    REQUIRE(c.cylinder.radius > 0.0);
    REQUIRE(c.cachedObject == cached.hit);
    // A hit is not a miss: no cause
    rc::RayFocus hit = *focus;
    hit.decision = rc::Decision::Hit;
    REQUIRE_FALSE(rc::missCauseOf(s, hit).valid());
}

TEST_CASE("Next miss and the event log keep to one miss reason", "[gui][tour][miss]") {
    GuiOptions o;
    QString why;
    REQUIRE(parseGuiOptions({"raycache-gui", "cube:3", "--width", "48", "--height", "48", "--cache", "blocker",
                             "--order", "scanline", "--steps", "3000", "--panels", "event-log"},
                            o, why) == ParseResult::Ok);
    MainWindow w;
    showAt(w, 1000, 700);
    REQUIRE(w.apply(o, true));
    w.setMissFilter(rc::MissReason::TargetMissed);
    const auto before = stateOf(w).session().steps();
    w.runToNextMiss();
    w.controller().wait();
    QApplication::processEvents();
    const rc::SessionState& s = stateOf(w);
    REQUIRE(s.session().steps() > before);
    REQUIRE(s.stopEvent() >= 0);
    REQUIRE(s.recorder().events()[std::size_t(s.stopEvent())].missReason() == rc::MissReason::TargetMissed);
    // The log shows exactly the misses of that reason, counted here from the recorder
    EventLogModel* model = w.eventLogPanel()->model();
    REQUIRE(model->reason() == rc::MissReason::TargetMissed);
    std::vector<int> expected;
    for (std::size_t i = 0; i < s.recorder().events().size(); ++i) {
        const rc::EventRecord& r = s.recorder().events()[i];
        if (!r.deferred() && r.rayDecision() == rc::Decision::Miss && r.missReason() == rc::MissReason::TargetMissed)
            expected.push_back(int(i));
    }
    REQUIRE(!expected.empty());
    REQUIRE(model->rowCount() == int(expected.size()));
    for (int row = 0; row < model->rowCount(); ++row) REQUIRE(model->eventAt(row) == expected[std::size_t(row)]);
    // The decision column is the last, so it is never cut, and it holds the whole decision
    const QModelIndex last = model->index(0, model->columnCount() - 1);
    REQUIRE(model->headerData(model->columnCount() - 1, Qt::Horizontal, Qt::DisplayRole).toString() == "decision");
    REQUIRE(model->data(last, Qt::DisplayRole).toString().startsWith("miss: target_missed"));
}

TEST_CASE("A click outside the image lets the selection go", "[gui][tour]") {
    GuiOptions o;
    QString why;
    REQUIRE(parseGuiOptions({"raycache-gui", "pair", "--width", "32", "--height", "32", "--steps", "2000", "--select",
                             "16,16"},
                            o, why) == ParseResult::Ok);
    MainWindow w;
    showAt(w, 1200, 700);
    REQUIRE(w.apply(o, true));
    REQUIRE(w.selection().pixel == 16 * 32 + 16);
    ImageView* v = w.imageView();
    // A point of the view left of the image (the image is fitted, centred in a wide view)
    const QPointF outside(2.0, v->height() / 2.0);
    REQUIRE_FALSE(v->pixelAt(outside));
    QMouseEvent press(QEvent::MouseButtonPress, outside, v->mapToGlobal(outside), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QMouseEvent release(QEvent::MouseButtonRelease, outside, v->mapToGlobal(outside), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(v, &press);
    QApplication::sendEvent(v, &release);
    REQUIRE(w.selection().pixel == -1);
}

TEST_CASE("The frame log (--frame-log) writes one line per UI-thread task, first-frame among them", "[gui][tour][cli]") {
    QTemporaryDir dir;
    const QString log = dir.filePath("frames.txt");
    QProcess gui;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    gui.setProcessEnvironment(env);
    gui.start(RAYCACHE_GUI, {"--tour", QDir(toursFolder()).filePath("hanrahan86.json"), "--stop", "4", "--window",
                             "1280x720", "--large-fonts", "--screenshot", dir.filePath("stop4.png"), "--frame-log", log});
    REQUIRE(gui.waitForFinished(120000));
    REQUIRE(gui.exitCode() == 0);
    QFile f(log);
    REQUIRE(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    const QRegularExpression format("^\\S+ \\d+\\.\\d{3}$");
    int paints = 0, firstFrames = 0, stops = 0;
    for (const QString& line : lines) {
        INFO(line.toStdString());
        REQUIRE(format.match(line).hasMatch());
        if (line.startsWith("Paint:")) ++paints;
        if (line.startsWith("first-frame ")) ++firstFrames;
        if (line.startsWith("stop-4 ")) ++stops;
    }
    REQUIRE(firstFrames == 1);
    REQUIRE(stops == 1);
    REQUIRE(paints >= 2);  // the screenshot's two grabs paint the window
    // The screenshot is the window's size
    QImage shot(dir.filePath("stop4.png"));
    REQUIRE(shot.size() == QSize(1280, 720));
    // A bad tour: file:line:column and exit 2
    QFile bad(dir.filePath("bad.json"));
    REQUIRE(bad.open(QIODevice::WriteOnly));
    bad.write("{\"stops\": [\n  {\"title\": \"x\", \"caption\": \"y.\", \"scene\": \"pair\", \"zoom\": \"big\"}]}");
    bad.close();
    gui.start(RAYCACHE_GUI, {"--tour", bad.fileName(), "--screenshot", dir.filePath("bad.png")});
    REQUIRE(gui.waitForFinished(60000));
    REQUIRE(gui.exitCode() == 2);
    REQUIRE(QString::fromUtf8(gui.readAllStandardError()).contains(bad.fileName() + ":2:3: stop 1 (x): --zoom"));
}

TEST_CASE("The event log holds the newest rays of a long render, a bounded number of rows", "[gui][stall]") {
    rc::SessionState s = pairState(rc::OrderKind::Scanline, 256);
    EventLogModel model;
    // Grown a step at a time, as a live window refreshes
    for (std::int64_t step : {20000, 60000, 90000}) {
        REQUIRE(s.runUntil(rc::RunGoal::ToStep, step));
        model.setState(&s);
        REQUIRE(model.total() == int(s.recorder().events().size()));
        REQUIRE(model.rowCount() == std::min(model.total(), EventLogModel::kMaxRows));
    }
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    model.setState(&s);
    const int events = int(s.recorder().events().size());
    REQUIRE(events > EventLogModel::kMaxRows);
    REQUIRE(model.total() == events);
    REQUIRE(model.rowCount() == EventLogModel::kMaxRows);
    // The rows are the newest events, oldest first
    REQUIRE(model.eventAt(0) == events - EventLogModel::kMaxRows);
    REQUIRE(model.eventAt(model.rowCount() - 1) == events - 1);
    REQUIRE(model.data(model.index(model.rowCount() - 1, 0), Qt::DisplayRole).toLongLong() ==
            s.recorder().events()[std::size_t(events - 1)].step);
    // Misses only: the misses and deferrals, newest last
    REQUIRE(!s.recorder().misses().empty());
    model.setMissesOnly(true);
    REQUIRE(model.total() == int(s.recorder().misses().size()));
    REQUIRE(model.rowCount() == std::min(model.total(), EventLogModel::kMaxRows));
    REQUIRE(model.eventAt(model.rowCount() - 1) == s.recorder().misses()[s.recorder().misses().size() - 1]);
}

TEST_CASE("The misses and region layers read a long log over several paints", "[gui][stall]") {
    rc::SessionState s = pairState(rc::OrderKind::BreadthFirst, 64);
    REQUIRE(s.runUntil(rc::RunGoal::ToStep, 6000));
    const std::size_t events = s.recorder().events().size();
    const std::size_t budget = 1000;
    REQUIRE(events > 3 * budget);
    OverlayPainter painter;
    int asked = 0;
    painter.setEventBudget(budget, [&] { ++asked; });
    Overlays o;
    o.misses = o.frontier = true;
    QImage target(64, 64, QImage::Format_ARGB32_Premultiplied);
    // Each paint reads a budget's worth of events into each layer, and asks for the next
    int paints = 0;
    do {
        QPainter p(&target);
        painter.paint(p, s, o, rc::Selection{}, 1.0);
        ++paints;
    } while (painter.layersPending() && paints < 1000);
    REQUIRE(!painter.layersPending());
    REQUIRE(std::size_t(paints) == (events + budget - 1) / budget);
    REQUIRE(asked == paints - 1);
    // With the log read, more events cost one more paint, and nothing is asked for
    REQUIRE(s.runUntil(rc::RunGoal::ToStep, 6500));
    REQUIRE(s.recorder().events().size() - events < budget);
    {
        QPainter p(&target);
        painter.paint(p, s, o, rc::Selection{}, 1.0);
    }
    REQUIRE(!painter.layersPending());
    REQUIRE(asked == paints - 1);
}
