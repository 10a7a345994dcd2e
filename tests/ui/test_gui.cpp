// GUI tests: stepping, overlays, clicks, scene errors, the worker, screenshots.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QMouseEvent>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>

#include "gui_options.h"
#include "image_view.h"
#include "labels.h"
#include "main_window.h"
#include "window_fixture.h"
#include "palette.h"
#include "projector.h"
#include "view/ray_focus.h"
#include "ray_tree_panel.h"
#include "screenshot.h"
#include "stats_panel.h"

using namespace rcgui;

namespace {

// A window on a small scene with errors collected instead of shown
struct Fixture {
    MainWindow w;
    QStringList errors;
    explicit Fixture(const QString& scene = "pair", rc::CacheKind cache = rc::CacheKind::Blocker,
                     rc::OrderKind order = rc::OrderKind::BreadthFirst) {
        w.setErrorReporter([this](const QString&, const QString& m) { errors << m; });
        w.setCache(cache);
        w.setOrder(order);
        REQUIRE(w.loadScene(scene));
        rcgui::testing::showAt(w, 1200, 900);
        w.imageView()->fit();
    }
    rc::SessionState& state() { return rcgui::testing::stateOf(w); }
    QImage grabView() {
        w.refresh();
        QApplication::processEvents();
        return w.imageView()->grab().toImage();
    }
};

int committed(const rc::SessionState& s) {
    int n = 0;
    for (const rc::EventRecord& r : s.recorder().events()) n += r.deferred() ? 0 : 1;
    return n;
}

double colourDistance(const QColor& a, const QColor& b) {
    return std::sqrt(std::pow(a.red() - b.red(), 2) + std::pow(a.green() - b.green(), 2) +
                     std::pow(a.blue() - b.blue(), 2));
}

// The best match to `want` within a few pixels of `at` (antialiased strokes)
double nearestColour(const QImage& img, QPointF at, const QColor& want, int radius = 2) {
    double best = 1e9;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = int(std::lround(at.x())) + dx, y = int(std::lround(at.y())) + dy;
            if (x < 0 || y < 0 || x >= img.width() || y >= img.height()) continue;
            best = std::min(best, colourDistance(img.pixelColor(x, y), want));
        }
    return best;
}

// The vertex of an outline farthest from the caption (top left) that lies in the view
QPointF farVertex(const QPolygonF& poly, const ImageView& view) {
    QPointF best(-1, -1);
    double score = -1;
    for (const QPointF& p : poly) {
        const QPointF w = view.imageToWidget(p);
        // Inside the view, out of the strip it keeps for the key (nothing is drawn there)
        if (w.x() < 4 || w.y() < 4 || w.x() > view.width() - view.reserve() - 4 || w.y() > view.height() - 4) continue;
        if (w.x() + w.y() > score) {
            score = w.x() + w.y();
            best = w;
        }
    }
    return best;
}

Overlays only(bool Overlays::*field) {
    Overlays o;
    o.legend = false;
    o.grid = false;
    if (field) o.*field = true;
    return o;
}

}  // namespace

TEST_CASE("Step ray advances exactly one ray", "[gui][step]") {
    Fixture f;
    // Step until some rays were deferred (bfs + blocker), and 200 steps past the first
    // deferral; each step repaints the window, so no more than that
    int pastDeferral = 0;
    for (int i = 0; i < 3000 && pastDeferral < 200; ++i) {
        const std::int64_t steps = f.state().session().steps();
        const int before = committed(f.state());
        f.w.stepRay();
        REQUIRE(f.state().session().steps() == steps + 1);
        REQUIRE(committed(f.state()) == before + 1);
        REQUIRE(f.state().recorder().lastCommitted()->step == steps);
        pastDeferral += f.state().session().counters().deferrals > 0;
    }
    // Deferrals happened, yet each step committed exactly one ray
    REQUIRE(pastDeferral == 200);
}

TEST_CASE("Step pixel stops on the first ray of another pixel", "[gui][step]") {
    Fixture f("pair", rc::CacheKind::Blocker, rc::OrderKind::Scanline);
    f.w.stepRay();
    const int first = f.state().recorder().lastCommitted()->task.pixel;
    f.w.stepPixel();
    f.w.controller().wait();
    const auto& events = f.state().recorder().events();
    REQUIRE(events.back().pixel != first);
    for (std::size_t i = 0; i + 1 < events.size(); ++i) REQUIRE(events[i].pixel == first);
}

TEST_CASE("Next miss stops on a committed miss and puts it in focus, Next deferral on a deferral", "[gui][step][focus]") {
    Fixture f;
    f.w.runToNextMiss();
    f.w.controller().wait();
    const int miss = f.state().stopEvent();
    REQUIRE(miss >= 0);
    const rc::EventRecord& m = f.state().recorder().events()[std::size_t(miss)];
    REQUIRE_FALSE(m.deferred());
    REQUIRE(m.rayDecision() == rc::Decision::Miss);
    REQUIRE(m.missReason() != rc::MissReason::None);
    // No committed miss before it
    for (int i = 0; i < miss; ++i) {
        const rc::EventRecord& r = f.state().recorder().events()[std::size_t(i)];
        REQUIRE((r.deferred() || r.rayDecision() != rc::Decision::Miss));
    }
    auto focus = rc::RayFocus::of(f.state(), f.w.selection());
    REQUIRE(focus);
    REQUIRE(focus->event == miss);
    REQUIRE(focus->decision == rc::Decision::Miss);
    REQUIRE(focus->reason == m.missReason());

    f.w.runToNextDeferral();
    f.w.controller().wait();
    const int deferral = f.state().stopEvent();
    REQUIRE(deferral > miss);
    REQUIRE(f.state().recorder().events()[std::size_t(deferral)].deferred());
    focus = rc::RayFocus::of(f.state(), f.w.selection());
    REQUIRE(focus);
    REQUIRE(focus->event == deferral);
    REQUIRE(focus->deferred);
}

TEST_CASE("Step back replays to the previous step", "[gui][step]") {
    Fixture f;
    for (int i = 0; i < 40; ++i) f.w.stepRay();
    const QImage at39 = [&] {
        rc::SessionState s(f.state().config());
        s.runUntil(rc::RunGoal::ToStep, 39);
        return SessionController::imageOf(s);
    }();
    f.w.stepBack();
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 39);
    REQUIRE(SessionController::imageOf(f.state()) == at39);
}

TEST_CASE("A click maps to the image pixel under it, at any zoom", "[gui][view]") {
    ImageView view;
    view.resize(400, 300);
    view.setImage(QImage(64, 48, QImage::Format_RGB32));
    view.show();
    QApplication::processEvents();
    QPoint got(-1, -1);
    QObject::connect(&view, &ImageView::pixelClicked, [&](int x, int y) { got = QPoint(x, y); });
    auto click = [&](QPointF at) {
        QMouseEvent press(QEvent::MouseButtonPress, at, view.mapToGlobal(at), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
        QMouseEvent release(QEvent::MouseButtonRelease, at, view.mapToGlobal(at), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(&view, &press);
        QApplication::sendEvent(&view, &release);
    };
    for (double zoom : {1.0, 5.0, 13.5}) {
        view.setZoom(zoom, QPointF(-30.0, -20.0));
        // The centre of pixel (12, 7) and a point just inside its top-left corner
        click(QPointF(-30.0 + zoom * 12.5, -20.0 + zoom * 7.5));
        REQUIRE(got == QPoint(12, 7));
        click(QPointF(-30.0 + zoom * 12.1, -20.0 + zoom * 7.1));
        REQUIRE(got == QPoint(12, 7));
    }
    // Wheel zoom keeps the point under the cursor
    const QPointF anchor(200, 150);
    const QPointF before = view.widgetToImage(anchor);
    view.zoomAt(2.0, anchor);
    REQUIRE(std::abs(view.widgetToImage(anchor).x() - before.x()) < 1e-9);
    REQUIRE(std::abs(view.widgetToImage(anchor).y() - before.y()) < 1e-9);
}

TEST_CASE("Clicking the view selects the pixel and shows its ray tree", "[gui][view]") {
    Fixture f;
    f.state().runUntil(rc::RunGoal::ToEnd, 0);
    f.w.refresh();
    ImageView* v = f.w.imageView();
    v->setZoom(6.0, QPointF(-400.0, -300.0));
    const QPointF at = v->imageToWidget(QPointF(120.5, 100.5));
    QMouseEvent press(QEvent::MouseButtonPress, at, v->mapToGlobal(at), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QMouseEvent release(QEvent::MouseButtonRelease, at, v->mapToGlobal(at), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(v, &press);
    QApplication::sendEvent(v, &release);
    REQUIRE(f.w.selection().pixel == 100 * f.state().width() + 120);
    REQUIRE(f.w.rayTreePanel()->topLevelItemCount() == 1);  // the eye ray, its children below
}

TEST_CASE("The blocker hull overlay outlines the target green and the blockers orange", "[gui][overlay]") {
    Fixture f("cube:3");
    // Trace until the ray being traced hit an object whose blocker list is not empty
    const rc::BlockerLists* lists = f.state().session().strategy().blockerLists();
    REQUIRE(lists != nullptr);
    const std::vector<int>* blockers = nullptr;
    int target = -1;
    for (int i = 0; i < 200000 && !blockers; ++i) {
        REQUIRE(f.state().step());
        const auto& e = f.state().recorder().lastEvent();
        if (e->deferred || e->task.query.kind != rc::RayKind::Primary || e->lookup.answer().object < 0) continue;
        // The pair of sites of this eye ray: the eye and the object it hit (no tiles in blocker)
        const rc::Query& q = e->task.query;
        const int site = lists->pointSite(e->lookup.answer().object, q.ray.at(e->lookup.answer().t));
        const std::vector<int>* l = lists->find(lists->originSite(q), site);
        if (l && !l->empty()) {
            blockers = l;
            target = site;
        }
    }
    REQUIRE(blockers != nullptr);
    f.w.setOverlays(only(nullptr));
    const QImage plain = f.grabView();
    f.w.setOverlays(only(&Overlays::hull));
    const QImage hull = f.grabView();
    REQUIRE(plain != hull);
    const Projector proj(f.state().scene().camera, f.state().camera());
    const QPointF t = farVertex(proj.silhouette(f.state().scene().objects[target].bound), *f.w.imageView());
    REQUIRE(t.x() >= 0);
    REQUIRE(nearestColour(hull, t, palette::kTarget) < 60);
    REQUIRE(nearestColour(plain, t, palette::kTarget) > 60);
    // Some blocker's outline is orange where it does not overlap the target
    bool orange = false;
    for (int b : *blockers) {
        const QPointF p = farVertex(proj.silhouette(f.state().scene().objects[b].bound), *f.w.imageView());
        if (p.x() >= 0 && nearestColour(hull, p, palette::kBlocker) < 60) orange = true;
    }
    REQUIRE(orange);
}

TEST_CASE("The cylinder overlay draws the active entry's capsule", "[gui][overlay]") {
    Fixture f("pair", rc::CacheKind::Cylinder, rc::OrderKind::Scanline);
    // A reflection ray: its capsule does not contain the eye, so it projects to a hull
    rc::SafetyCylinder cyl;
    for (int i = 0; i < 200000; ++i) {
        REQUIRE(f.state().step());
        const auto& e = f.state().recorder().lastEvent();
        if (e->task.query.kind != rc::RayKind::Reflection) continue;
        const rc::CacheEntry& entry = f.state().session().cacheTree().entry(e->task.node);
        if (entry.cylinder.radius > 0.02) {
            cyl = entry.cylinder;
            break;
        }
    }
    REQUIRE(cyl.radius > 0.0);
    f.w.setOverlays(only(nullptr));
    const QImage plain = f.grabView();
    f.w.setOverlays(only(&Overlays::cylinder));
    const QImage drawn = f.grabView();
    const Projector proj(f.state().scene().camera, f.state().camera());
    const QPointF p = farVertex(proj.hull({cyl.a, cyl.radius}, {cyl.b, cyl.radius}), *f.w.imageView());
    REQUIRE(p.x() >= 0);
    REQUIRE(nearestColour(drawn, p, palette::kCylinder) < 60);
    REQUIRE(nearestColour(plain, p, palette::kCylinder) > 60);
}

TEST_CASE("The frontier overlay marks queued pixels", "[gui][overlay]") {
    Fixture f("pair");
    rc::FrontierView fr;
    for (int i = 0; i < 50000; ++i) {
        REQUIRE(f.state().step());
        if (i > 2000 && !(fr = f.state().session().order().frontier()).queued.empty()) break;
    }
    REQUIRE(!fr.queued.empty());
    const int w = f.state().width();
    const int px = fr.queued.back();
    // Centre the view on it, away from the caption at the top left
    ImageView& view = *f.w.imageView();
    const QPointF centre(px % w + 0.5, px / w + 0.5);
    view.setZoom(view.zoom(), QPointF(view.width() / 2.0, view.height() / 2.0) - view.zoom() * centre);
    f.w.setOverlays(only(nullptr));
    const QImage plain = f.grabView();
    f.w.setOverlays(only(&Overlays::frontier));
    const QImage drawn = f.grabView();
    const QPointF at = view.imageToWidget(centre);
    REQUIRE(colourDistance(drawn.pixelColor(at.toPoint()), palette::kQueued) < 40);
    REQUIRE(colourDistance(plain.pixelColor(at.toPoint()), palette::kQueued) > 40);
}

TEST_CASE("The miss overlay marks misses in their reason's colour", "[gui][overlay]") {
    Fixture f("pair");
    f.state().runUntil(rc::RunGoal::ToStep, 20000);
    const rc::TraceRecorder& rec = f.state().recorder();
    const int path = rec.lastEvent()->task.node;
    int pixel = -1;
    rc::MissReason reason = rc::MissReason::None;
    for (int px = 0; px < f.state().width() * f.state().height() && pixel < 0; ++px) {
        const int i = rec.eventAt(px, path);
        if (i >= 0 && rec.events()[i].rayDecision() == rc::Decision::Miss) {
            pixel = px;
            reason = rec.events()[i].missReason();
        }
    }
    REQUIRE(pixel >= 0);
    // The pixel in the middle of what the view shows (out of the strip it keeps for the key)
    const ImageView& view = *f.w.imageView();
    const QPointF middle((view.width() - view.reserve()) / 2.0, view.height() / 2.0);
    f.w.imageView()->setZoom(8.0, QPointF(0, 0) - 8.0 * QPointF(pixel % f.state().width(), pixel / f.state().width()) + middle);
    f.w.setOverlays(only(nullptr));
    const QImage plain = f.grabView();
    f.w.setOverlays(only(&Overlays::misses));
    const QImage drawn = f.grabView();
    const QPoint at = f.w.imageView()->imageToWidget(QPointF(pixel % f.state().width() + 0.5, pixel / f.state().width() + 0.5)).toPoint();
    REQUIRE(colourDistance(drawn.pixelColor(at), palette::missReason(reason)) < 40);
    REQUIRE(plain.pixelColor(at) != drawn.pixelColor(at));
}

TEST_CASE("Overlays the cache and order cannot draw are not offered", "[gui][overlay]") {
    Fixture none("pair", rc::CacheKind::None, rc::OrderKind::Scanline);
    REQUIRE(none.w.offeredOverlays().isEmpty());
    Fixture cyl("pair", rc::CacheKind::Cylinder, rc::OrderKind::Scanline);
    REQUIRE(cyl.w.offeredOverlays() == QStringList{"Cylinder", "Misses"});
    Fixture all("pair", rc::CacheKind::Blocker, rc::OrderKind::BreadthFirst);
    REQUIRE(all.w.offeredOverlays() == QStringList{"Cylinder", "Hull", "Frontier", "Misses"});
}

TEST_CASE("Every cache can be chosen, and each blocker cache offers its hulls", "[gui][overlay]") {
    for (rc::CacheKind k : {rc::CacheKind::BlockerPlus, rc::CacheKind::BlockerDirections}) {
        Fixture f("pair", k, rc::OrderKind::BreadthFirst);
        const QString label = text(rc::toString(k));
        INFO(label.toStdString());
        REQUIRE(f.w.cacheChoices() == QStringList{"none", "cylinder", "blocker", "blocker+", "blocker+dir"});
        REQUIRE(f.w.cacheShown() == label);
        REQUIRE(f.w.offeredOverlays().contains("Hull"));
        REQUIRE(f.w.offeredOverlays().contains("Frontier"));
        QString error;
        REQUIRE(f.w.setCompare(label + ":scanline", error));
        REQUIRE(error.isEmpty());
    }
}

TEST_CASE("The statistics say how RayCache's caches answered: direction lists, paths stepped aside", "[gui][stats]") {
    auto finished = [](Fixture& f) {
        f.w.runToEnd();
        f.w.controller().wait();
        f.w.refresh();
        QApplication::processEvents();
        return f.w.statsPanel()->summaryText();
    };
    Fixture directed("pair", rc::CacheKind::BlockerDirections, rc::OrderKind::BreadthFirst);
    const QString d = finished(directed);
    REQUIRE(directed.state().session().counters().directionSearches > 0);
    REQUIRE(d.contains("direction lists"));
    REQUIRE_FALSE(d.contains("stepped aside"));
    // In front of a hierarchy, blocker+ steps aside on paths whose rays mostly search
    Fixture aside("pair", rc::CacheKind::BlockerPlus, rc::OrderKind::BreadthFirst);
    aside.w.setAccel(rc::AccelKind::Bvh);
    const QString a = finished(aside);
    REQUIRE(aside.state().session().counters().steppedAside > 0);
    REQUIRE(a.contains("stepped aside"));
    REQUIRE_FALSE(a.contains("direction lists"));
}

TEST_CASE("Heatmaps replace the image", "[gui][overlay]") {
    Fixture f("pair");
    f.state().runUntil(rc::RunGoal::ToStep, 30000);
    f.w.setHeatmap(Heatmap::None);
    const QImage image = f.w.imageView()->image();
    for (Heatmap h : {Heatmap::Tests, Heatmap::HitMiss, Heatmap::VisitOrder, Heatmap::BeamNode}) {
        f.w.setHeatmap(h);
        REQUIRE(f.w.imageView()->image().size() == image.size());
        REQUIRE(f.w.imageView()->image() != image);
    }
}

TEST_CASE("A malformed scene is reported and the previous scene kept", "[gui][scene]") {
    Fixture f("pair");
    for (int i = 0; i < 10; ++i) f.w.stepRay();
    const rc::Scene* before = f.w.scene();
    QTemporaryDir dir;
    REQUIRE(dir.isValid());
    const QString path = dir.filePath("bad.nff");
    QFile file(path);
    REQUIRE(file.open(QIODevice::WriteOnly));
    file.write("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\ns 0 0 banana 1\n");
    file.close();
    REQUIRE_FALSE(f.w.loadScene(path));
    REQUIRE(f.errors.size() == 1);
    REQUIRE(f.errors[0].contains("bad.nff:8:"));
    REQUIRE(f.w.scene() == before);
    REQUIRE(f.state().session().steps() == 10);  // the render goes on where it was
    f.w.stepRay();
    REQUIRE(f.state().session().steps() == 11);
}

TEST_CASE("A run on the worker can be cancelled and the window stays usable", "[gui][worker]") {
    Fixture f("cube:8", rc::CacheKind::None, rc::OrderKind::Scanline);
    bool snapshot = false;
    QObject::connect(&f.w.controller(), &SessionController::snapshot, [&] { snapshot = true; });
    f.w.runToEnd();
    REQUIRE(f.w.controller().busy());
    REQUIRE(f.w.controller().state() == nullptr);  // the worker owns the state
    QElapsedTimer t;
    t.start();
    while (!snapshot && t.elapsed() < 5000) QApplication::processEvents(QEventLoop::AllEvents, 20);
    REQUIRE(snapshot);  // the window kept processing events while the worker ran
    f.w.cancelRun();
    f.w.controller().wait();
    REQUIRE_FALSE(f.w.controller().busy());
    REQUIRE_FALSE(f.state().session().done());
    const std::int64_t steps = f.state().session().steps();
    REQUIRE(steps > 0);
    f.w.stepRay();
    REQUIRE(f.state().session().steps() == steps + 1);
}

TEST_CASE("Closing the window during a run stops the worker", "[gui][worker]") {
    auto* w = new MainWindow;
    w->setErrorReporter([](const QString&, const QString&) {});
    w->setCache(rc::CacheKind::None);
    w->setOrder(rc::OrderKind::Scanline);
    REQUIRE(w->loadScene("cube:8"));
    w->show();
    w->runToEnd();
    REQUIRE(w->controller().busy());
    w->close();
    REQUIRE_FALSE(w->controller().busy());
    delete w;
}

TEST_CASE("Command line options parse, and bad ones are errors", "[gui][cli]") {
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui", "cube:4", "--cache", "cylinder", "--order", "progressive", "--steps", "12",
                             "--overlays", "cylinder,cone,frontier,misses", "--heatmap", "tests", "--screenshot", "x.png"},
                            o, msg) == ParseResult::Ok);
    REQUIRE(o.scene == "cube:4");
    REQUIRE(o.cache == rc::CacheKind::Cylinder);
    REQUIRE(o.order == rc::OrderKind::Progressive);
    REQUIRE(o.steps == 12);
    REQUIRE((o.overlays.cylinder && o.overlays.hull && o.overlays.frontier && o.overlays.misses));
    REQUIRE(o.heatmap == Heatmap::Tests);
    GuiOptions bad;
    REQUIRE(parseGuiOptions({"raycache-gui", "--cache", "lru"}, bad, msg) == ParseResult::Error);
    REQUIRE(msg.contains("--cache"));
    REQUIRE(parseGuiOptions({"raycache-gui", "--overlays", "sparkles"}, bad, msg) == ParseResult::Error);
    REQUIRE(parseGuiOptions({"raycache-gui", "--bogus"}, bad, msg) == ParseResult::Error);
}

TEST_CASE("Screenshot mode writes a PNG of the window", "[gui][screenshot]") {
    QTemporaryDir dir;
    GuiOptions o;
    o.scene = "pair";
    o.steps = 3000;
    o.overlays = *Overlays::parse("cylinder,cone,frontier,misses");
    o.screenshot = dir.filePath("shot.png");
    o.window = QSize(900, 700);
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    REQUIRE(renderScreenshot(o, out, err) == 0);
    QImage img(o.screenshot);
    REQUIRE(!img.isNull());
    REQUIRE(img.width() >= 900);
    std::set<QRgb> colours;
    for (int y = 0; y < img.height(); y += 3)
        for (int x = 0; x < img.width(); x += 3) colours.insert(img.pixel(x, y));
    REQUIRE(colours.size() > 100);
}

TEST_CASE("With large fonts the window fits a 1280x720 projector", "[gui][screenshot]") {
    // Before the right-hand panels ran the window's full height, the window could not be
    // made shorter than 818 pixels with large fonts
    QTemporaryDir dir;
    GuiOptions o;
    o.scene = "cube:3";
    o.width = o.height = 96;
    o.steps = 2000;
    o.largeFonts = true;
    o.screenshot = dir.filePath("projector.png");
    o.window = QSize(1280, 720);
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    REQUIRE(renderScreenshot(o, out, err) == 0);
    const QImage img(o.screenshot);
    REQUIRE(img.width() == 1280);
    REQUIRE(img.height() == 720);
}

TEST_CASE("The executable exits 2 on a bad scene and 0 on a screenshot", "[gui][screenshot]") {
    QTemporaryDir dir;
    const QString bad = dir.filePath("broken.nff");
    QFile file(bad);
    REQUIRE(file.open(QIODevice::WriteOnly));
    file.write("s 0 0 0\n");
    file.close();
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    env.remove("QT_QPA_PLATFORM");
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(RAYCACHE_GUI, {bad, "--screenshot", dir.filePath("never.png")});
    REQUIRE(p.waitForFinished(60000));
    REQUIRE(p.exitCode() == 2);
    const QString errText = QString::fromLocal8Bit(p.readAllStandardError());
    REQUIRE(errText.contains("broken.nff:"));
    REQUIRE_FALSE(QFile::exists(dir.filePath("never.png")));

    p.start(RAYCACHE_GUI, {"pair", "--steps", "500", "--screenshot", dir.filePath("ok.png"), "--window", "640x480"});
    REQUIRE(p.waitForFinished(60000));
    REQUIRE(p.exitCode() == 0);
    REQUIRE(QString::fromLocal8Bit(p.readAllStandardOutput()).contains("headless"));
    REQUIRE(!QImage(dir.filePath("ok.png")).isNull());

    p.start(RAYCACHE_GUI, {"--order", "sideways"});
    REQUIRE(p.waitForFinished(60000));
    REQUIRE(p.exitCode() == 2);
}
