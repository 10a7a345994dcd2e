// GUI tests: a second render compared in lockstep, the scene view (the paper's Figures
// 1 and 2 reproduced on the trio scene), and what recording costs per ray.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QProcess>
#include <QTemporaryDir>

#include <glm/geometric.hpp>

#include "geometry/safety_cylinder.h"
#include "gui_options.h"
#include "heatmap_builder.h"
#include "image_view.h"
#include "main_window.h"
#include "window_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene_view.h"
#include "stats_panel.h"

using namespace rcgui;

namespace {

struct Window {
    MainWindow w;
    QStringList errors;
    explicit Window(const QString& scene, rc::CacheKind cache = rc::CacheKind::Blocker,
                    rc::OrderKind order = rc::OrderKind::BreadthFirst) {
        w.setErrorReporter([this](const QString&, const QString& m) { errors << m; });
        w.setCache(cache);
        w.setOrder(order);
        REQUIRE(w.loadScene(scene));
        rcgui::testing::showAt(w, 1400, 900);
    }
    rc::SessionState& state() { return rcgui::testing::stateOf(w); }
    rc::SessionState& compared() {
        w.compareController().wait();
        rc::SessionState* s = w.compareController().state();
        REQUIRE(s != nullptr);
        return *s;
    }
    // Runs the first render to `step` on its worker and lets the compared one catch up
    void goTo(qint64 step) {
        w.goToStep(step);
        w.controller().wait();
        w.compareController().wait();
    }
};

}  // namespace

TEST_CASE("Compare runs a second render in lockstep: same step count, forwards and backwards", "[gui][compare]") {
    Window f("pair");
    QString why;
    REQUIRE(f.w.setCompare("none:scanline", why));
    REQUIRE(f.w.compareChoice() == CompareChoice{rc::CacheKind::None, rc::OrderKind::Scanline});
    REQUIRE(f.compared().session().options().cache == rc::CacheKind::None);
    REQUIRE(f.compared().session().options().order == rc::OrderKind::Scanline);
    // A step on the first render: the second follows on the GUI thread
    for (int i = 0; i < 7; ++i) f.w.stepRay();
    REQUIRE(f.state().session().steps() == 7);
    REQUIRE(f.compared().session().steps() == 7);
    // A long way forwards: the second catches up on its own worker, not the GUI thread
    f.w.goToStep(20000);
    f.w.controller().wait();
    REQUIRE(f.w.compareController().busy());
    f.w.compareController().wait();
    REQUIRE(f.compared().session().steps() == 20000);
    // Backwards too
    f.goTo(1234);
    REQUIRE(f.state().session().steps() == 1234);
    REQUIRE(f.compared().session().steps() == 1234);
    REQUIRE(f.errors.isEmpty());
}

TEST_CASE("Compared renders end on the same image, and the statistics show the difference in tests", "[gui][compare]") {
    Window f("pair");
    QString why;
    REQUIRE(f.w.setCompare("none:scanline", why));
    f.w.runToEnd();
    f.w.controller().wait();
    f.w.compareController().wait();
    const rc::SessionState& a = f.state();
    const rc::SessionState& b = f.compared();
    REQUIRE(a.session().done());
    REQUIRE(b.session().done());
    REQUIRE(a.session().steps() == b.session().steps());
    // Caching never changes the picture: the two images agree byte for byte
    REQUIRE(SessionController::imageOf(a) == SessionController::imageOf(b));
    // Without a cache, every ray is a complete search: more tests than the blocker cache
    const auto ta = a.session().counters().intersectionTests, tb = b.session().counters().intersectionTests;
    REQUIRE(tb > ta);
    const QString stats = f.w.statsPanel()->summaryText();
    REQUIRE(stats.contains("compared"));
    REQUIRE(stats.contains(QString("+%1").arg(double(tb) - double(ta), 0, 'f', 0)));
}

TEST_CASE("Heatmaps of compared renders share one scale, the larger of the two", "[gui][compare][heatmap]") {
    Window f("pair");
    QString why;
    REQUIRE(f.w.setCompare("none:scanline", why));
    f.goTo(30000);
    f.w.setHeatmap(Heatmap::Tests);
    f.w.refresh();
    f.w.compareController().wait();
    f.w.imageView()->grab();
    f.w.compareView()->grab();
    const double own = HeatmapBuilder::scaleOf(f.state(), Heatmap::Tests);
    const double other = HeatmapBuilder::scaleOf(f.compared(), Heatmap::Tests);
    REQUIRE(own != other);
    REQUIRE(f.w.overlayPainter().heatmapTop() == std::max(own, other));
    REQUIRE(f.w.compareOverlayPainter().heatmapTop() == std::max(own, other));
    // Equal colours mean equal values: a pixel with the same tests in both has one colour
    const QImage ia = HeatmapBuilder::build(f.state(), Heatmap::Tests, 0, std::max(own, other));
    const QImage ib = HeatmapBuilder::build(f.compared(), Heatmap::Tests, 0, std::max(own, other));
    int same = 0;
    for (int px = 0; px < f.state().width() * f.state().height(); ++px) {
        const int x = px % f.state().width(), y = px / f.state().width();
        if (f.state().recorder().firstVisit(px) < 0 || f.compared().recorder().firstVisit(px) < 0) continue;
        if (f.state().recorder().testsAt(px) != f.compared().recorder().testsAt(px)) continue;
        REQUIRE(ia.pixel(x, y) == ib.pixel(x, y));
        ++same;
    }
    REQUIRE(same > 0);
}

TEST_CASE("Compare draws the overlays on the second render too", "[gui][compare][overlay]") {
    Window f("pair", rc::CacheKind::Blocker, rc::OrderKind::Scanline);
    QString why;
    REQUIRE(f.w.setCompare("blocker:bfs", why));
    f.goTo(3000);
    f.w.setOverlays(*Overlays::parse("cylinder,cone"));
    f.w.refresh();
    f.w.compareController().wait();
    f.w.compareView()->grab();
    REQUIRE(f.w.compareOverlayPainter().lastWork().outlines > 0);
}

TEST_CASE("A bad compare keeps the render and says why", "[gui][compare][cli]") {
    Window f("pair");
    QString why;
    REQUIRE(f.w.setCompare("cylinder:bfs", why));
    f.goTo(100);
    REQUIRE_FALSE(f.w.setCompare("fast:bfs", why));
    REQUIRE(why.contains("CACHE:ORDER"));
    REQUIRE(f.w.compareChoice() == CompareChoice{rc::CacheKind::Cylinder, rc::OrderKind::BreadthFirst});
    REQUIRE(f.state().session().steps() == 100);
    REQUIRE(f.compared().session().steps() == 100);
    REQUIRE(f.w.setCompare("off", why));
    REQUIRE_FALSE(f.w.compareChoice());
    REQUIRE(f.w.compareController().state() == nullptr);

    // Headless: exit 2 with the reason, and no picture
    QTemporaryDir dir;
    QProcess p;
    p.start(RAYCACHE_GUI, {"pair", "--compare", "none", "--screenshot", dir.filePath("never.png")});
    REQUIRE(p.waitForFinished(60000));
    REQUIRE(p.exitCode() == 2);
    REQUIRE(QString::fromLocal8Bit(p.readAllStandardError()).contains("--compare"));
    REQUIRE_FALSE(QFile::exists(dir.filePath("never.png")));
}

TEST_CASE("The compare and scene-view options parse, and bad ones are errors", "[gui][cli]") {
    auto parse = [](QStringList a, GuiOptions& o) {
        QString m;
        a.prepend("raycache-gui");
        return parseGuiOptions(a, o, m);
    };
    GuiOptions o;
    REQUIRE(parse({"pair", "--compare", "none:scanline"}, o) == ParseResult::Ok);
    REQUIRE(o.compare == CompareChoice{rc::CacheKind::None, rc::OrderKind::Scanline});
    GuiOptions side;
    REQUIRE(parse({"--scene-view", "trio"}, side) == ParseResult::Ok);
    REQUIRE(side.sceneView);
    REQUIRE(side.sceneAngle == SceneAngle::Side);
    REQUIRE(side.scene == "trio");
    GuiOptions along;
    REQUIRE(parse({"trio", "--scene-view", "along", "--orbit", "30,-10"}, along) == ParseResult::Ok);
    REQUIRE(along.sceneAngle == SceneAngle::Along);
    REQUIRE(along.orbitYaw == 30.0);
    REQUIRE(along.orbitPitch == -10.0);
    GuiOptions bad;
    for (const QStringList& a : {QStringList{"--compare", "blocker"}, QStringList{"--compare", "blocker:sideways"},
                                 QStringList{"--scene-view=upside"}, QStringList{"--orbit", "30"},
                                 QStringList{"--orbit", "0,95"}})
        REQUIRE(parse(a, bad) == ParseResult::Error);
}

TEST_CASE("Scene view, the paper's Figure 2: a side view of the hull between two spheres with a blocker inside", "[gui][sceneview]") {
    // trio: #0 the big mirror, #1 the small sphere it reflects, #2 placed inside their hull
    Window f("trio");
    f.goTo(200000);
    QString why;
    REQUIRE(f.w.selectRay(114, 135, "eye/reflection", why));
    f.w.setOverlays(*Overlays::parse("cone"));
    f.w.setSceneView(true);
    SceneView* v = f.w.sceneView();
    v->setAngle(SceneAngle::Side);
    const SceneSketch& k = v->sketch();
    REQUIRE(k.focus);
    REQUIRE(k.focus->kind == rc::RayKind::Reflection);
    REQUIRE(k.focus->origin.object == 0);
    REQUIRE(k.focus->hit == 1);
    REQUIRE(k.hull.valid());
    REQUIRE(k.hull.targetObject == 1);
    REQUIRE(std::count(k.hull.blockers.begin(), k.hull.blockers.end(), 2) == 1);
    v->grab();
    // Seen from the side: the hull's axis runs level, origin on the left, target on the right
    const QPointF a = v->toWidget(k.hull.a.c), b = v->toWidget(k.hull.b.c);
    REQUIRE(std::abs(a.y() - b.y()) < 1e-6);
    REQUIRE(a.x() < b.x());
    // The blocker's disc lies inside the hull's outline
    const rc::Sphere blocker = f.state().scene().objects[2].bound;
    const QPolygonF hull = discHull(a, k.hull.a.r * v->scale(), b, k.hull.b.r * v->scale());
    const QPointF c = v->toWidget(blocker.c);
    const double r = blocker.r * v->scale();
    for (int i = 0; i < 16; ++i) {
        const double t = 2 * M_PI * i / 16;
        REQUIRE(hull.containsPoint(c + r * QPointF(std::cos(t), std::sin(t)), Qt::OddEvenFill));
    }
    REQUIRE(v->caption().contains("potential blocker"));
}

TEST_CASE("Scene view, the paper's Figure 1: along the ray, the cylinder is much smaller than the sphere", "[gui][sceneview]") {
    Window f("trio", rc::CacheKind::Cylinder);
    f.goTo(200000);
    QString why;
    REQUIRE(f.w.selectRay(118, 116, "", why));
    f.w.setOverlays(*Overlays::parse("cylinder"));
    f.w.setSceneView(true);
    SceneView* v = f.w.sceneView();
    v->setAngle(SceneAngle::Along);
    const SceneSketch& k = v->sketch();
    REQUIRE(k.focus);
    REQUIRE(k.focus->hit == 0);
    v->grab();
    // Down the ray: its start and its hit are one point (the +)
    const rc::Vec3 end = k.focus->segmentEnd(f.state().scene());
    REQUIRE(QLineF(v->toWidget(k.focus->ray.o), v->toWidget(end)).length() < 0.5);
    // The radius is rc::safetyRadius's for this segment and every bounding sphere, the hit
    // (object 0) excepted; the sphere the view names as setting it has that gap alone
    const rc::Scene& scene = f.state().scene();
    std::vector<rc::Sphere> bounds;
    for (const rc::Object& o : scene.objects) bounds.push_back(o.bound);
    const double gap = rc::safetyRadius(bounds, 0, k.focus->ray.o, end);
    REQUIRE(k.cylinder.cylinder.radius == Approx(gap).epsilon(1e-6));
    REQUIRE(k.limiter > 0);
    REQUIRE(k.limiter < scene.size());
    REQUIRE(rc::safetyRadius({bounds[std::size_t(k.limiter)]}, -1, k.focus->ray.o, end) == Approx(gap).epsilon(1e-6));
    // Much smaller than the sphere it hits: under a third of its radius, a tenth of its area
    REQUIRE(k.cylinder.cylinder.radius < scene.objects[0].bound.r / 3);
    REQUIRE(v->caption().contains("cylinder of safety"));
}

TEST_CASE("Recording keeps at most 32 bytes per ray", "[gui][record]") {
    Window f("cube:3");
    f.goTo(150000);
    const rc::TraceRecorder& rec = f.state().recorder();
    const double events = double(rec.events().size());
    REQUIRE(events > 100000);
    REQUIRE(sizeof(rc::EventRecord) <= 56);
    // Counted from what is allocated (the log's chunks and group index, and the miss index)
    WARN("recording: " << double(rec.eventBytes()) / events << " bytes per event over " << events << " events");
    REQUIRE(double(rec.eventBytes()) / events <= 32.0);
}

TEST_CASE("A recorded direction stays within 1e-4 radians of the traced one", "[gui][record]") {
    Window f("glass");
    double worst = 0;
    for (int i = 0; i < 3000; ++i) {
        REQUIRE(f.state().step());
        const rc::Vec3 exact = glm::normalize(f.state().recorder().lastEvent()->task.query.ray.d);
        // As the log gives it back: traced again from its pixel and path when it keeps no ray
        const rc::Vec3 kept = f.state().event(f.state().recorder().events().size() - 1).rayDirection();
        worst = std::max(worst, std::acos(std::clamp(glm::dot(exact, kept), -1.0, 1.0)));
    }
    REQUIRE(worst < 1e-4);
}

TEST_CASE("The compared view zooms and pans with the first", "[gui][compare][view]") {
    Window f("pair");
    QString why;
    REQUIRE(f.w.setCompare("none:scanline", why));
    f.goTo(500);
    f.w.refresh();
    QApplication::processEvents();
    ImageView* a = f.w.imageView();
    ImageView* b = f.w.compareView();
    a->zoomAt(4.0, QPointF(a->width() / 2.0, a->height() / 2.0));
    REQUIRE(b->zoom() == Approx(a->zoom()));
    // The pixel under each view's centre is the same one
    const auto pa = a->pixelAt(QPointF(a->width() / 2.0, a->height() / 2.0));
    const auto pb = b->pixelAt(QPointF(b->width() / 2.0, b->height() / 2.0));
    REQUIRE(pa);
    REQUIRE(pb);
    REQUIRE(*pa == *pb);
    // And back: panning the second moves the first
    b->setZoom(b->zoom(), b->pan() + QPointF(37, -21));
    REQUIRE(a->pan().x() == Approx(b->pan().x() - (b->width() - a->width()) / 2.0));
    REQUIRE(a->pan().y() == Approx(b->pan().y() - (b->height() - a->height()) / 2.0));
}
