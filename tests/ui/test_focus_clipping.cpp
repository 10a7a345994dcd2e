// GUI tests: the ray in focus, clipping of shapes that reach the eye's plane, and a
// stall probe (how much the overlays draw, and the event loop's longest gap).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QDir>
#include <QTextStream>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>

#include <glm/geometric.hpp>

#include "gui_options.h"
#include "image_view.h"
#include "main_window.h"
#include "window_fixture.h"
#include "projector.h"
#include "view/ray_focus.h"
#include "ray_tree_panel.h"
#include "scene/builtin_scenes.h"
#include "scene/sphereflake.h"
#include "screenshot.h"

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
        rcgui::testing::showAt(w, 1000, 800);
        w.imageView()->fit();
    }
    rc::SessionState& state() { return rcgui::testing::stateOf(w); }
    void paint() {
        w.refresh();
        w.imageView()->grab();
    }
};

bool inside(const QPolygonF& poly, const QRectF& r) {
    for (const QPointF& p : poly)
        if (p.x() < r.left() - 1e-6 || p.x() > r.right() + 1e-6 || p.y() < r.top() - 1e-6 || p.y() > r.bottom() + 1e-6)
            return false;
    return true;
}

// The camera's frame
struct Frame {
    rc::Vec3 eye, forward, right, up;
    explicit Frame(const rc::Camera& c) : eye(c.from), forward(glm::normalize(c.at - c.from)) {
        right = glm::normalize(glm::cross(forward, c.up));
        up = glm::cross(right, forward);
    }
};

}  // namespace

TEST_CASE("A hull reaching a light level with the eye is clipped to the view", "[gui][clip]") {
    const rc::Scene scene = rc::loadScene("pair");
    const rc::RayGenerator rays(scene.camera, 256, 256);
    Projector proj(scene.camera, rays);
    const QRectF view(-20, -20, 296, 296);
    proj.setClip(view);
    const Frame fr(scene.camera);
    // An object in front, and a light beside the eye, exactly level with it (depth 0)
    const rc::Sphere object{fr.eye + fr.forward * 5.0, 0.5};
    const rc::Sphere light{fr.eye + fr.right * 3.0, 0.0};
    REQUIRE(proj.depth(light.c) == Approx(0.0).margin(1e-12));
    const QPolygonF hull = proj.hull(object, light);
    REQUIRE(hull.size() >= 3);
    REQUIRE(inside(hull, view));
    // It holds the object's centre, and it runs off the view's side towards the light
    const QPointF centre = *proj.point(object.c);
    REQUIRE(hull.containsPoint(centre, Qt::OddEvenFill));
    double rightmost = -1e9;
    for (const QPointF& p : hull) rightmost = std::max(rightmost, p.x());
    REQUIRE(rightmost == Approx(view.right()));
    REQUIRE_FALSE(proj.covers(hull));
    // The same hull unclipped reaches far beyond the image: clipping is what bounds it
    Projector open(scene.camera, rays);
    const QPolygonF unclipped = open.hull(object, light);
    double far = 0;
    for (const QPointF& p : unclipped) far = std::max(far, std::abs(p.x()));
    REQUIRE(far > 10 * view.right());
    // The ray's segment to the light is clipped too
    const auto seg = proj.segment(object.c, light.c);
    REQUIRE(seg);
    REQUIRE(inside(QPolygonF({seg->p1(), seg->p2()}), view));
    REQUIRE(seg->p2().x() == Approx(view.right()));
    // A light a little behind the eye's plane: the same
    const QPolygonF behind = proj.hull(object, {fr.eye + fr.right * 3.0 - fr.forward * 0.01, 0.0});
    REQUIRE(behind.size() >= 3);
    REQUIRE(inside(behind, view));
}

TEST_CASE("A sphere through the near plane, and a hull around the eye, are clipped", "[gui][clip]") {
    const rc::Scene scene = rc::loadScene("pair");
    const rc::RayGenerator rays(scene.camera, 128, 128);
    Projector proj(scene.camera, rays);
    const QRectF view(0, 0, 128, 128);
    proj.setClip(view);
    const Frame fr(scene.camera);
    // A sphere beside the eye, cut by the near plane: its front part shows, in the view
    const rc::Sphere cut{fr.eye + fr.forward * 0.2 + fr.right * 0.35, 0.3};
    REQUIRE(proj.depth(cut.c) - cut.r < proj.nearPlane());
    const QPolygonF s = proj.silhouette(cut);
    REQUIRE(s.size() >= 3);
    REQUIRE(inside(s, view));
    REQUIRE_FALSE(proj.covers(s));
    // The eye between two spheres: their hull holds it, so it fills the view
    const rc::Sphere before{fr.eye + fr.forward * 2.0, 0.5}, after{fr.eye - fr.forward * 2.0, 0.5};
    const QPolygonF around = proj.hull(before, after);
    REQUIRE(proj.covers(around));
    // A cone of eye rays reaching past 90 degrees from the view direction stays bounded
    const QPolygonF cone = proj.eyeCone(fr.forward + fr.right * 1.2, 1.0);
    REQUIRE(cone.size() >= 3);
    REQUIRE(inside(cone, view));
    // Clipping helpers
    REQUIRE(clipConvex(QPolygonF({{-100, 64}, {64, -100}, {300, 64}, {64, 300}}), view).size() >= 4);
    REQUIRE_FALSE(clipLine(QLineF(-10, -10, -5, 200), view));
    const auto l = clipLine(QLineF(-64, 64, 192, 64), view);
    REQUIRE(l);
    REQUIRE(l->p1().x() == Approx(0.0));
    REQUIRE(l->p2().x() == Approx(128.0));
}

TEST_CASE("Stall probe: overlays on a shadow ray level with the eye draw a bounded amount", "[gui][clip][stall]") {
    // cube:5 at step 49830 traces a shadow ray towards a light level with the camera
    // (the case that froze the window for seconds)
    Window f("cube:5");
    f.state().runUntil(rc::RunGoal::ToStep, 49830);
    f.w.setOverlays(*Overlays::parse("all"));
    f.paint();
    const PaintWork& work = f.w.overlayPainter().lastWork();
    REQUIRE(work.outlines > 0);
    // Every vertex lies within the widget's view (plus its margin) in image units, and the
    // outlines together are a few view perimeters long at most
    const ImageView& v = *f.w.imageView();
    const QPointF topLeft = v.widgetToImage(QPointF(0, 0)), bottomRight = v.widgetToImage(QPointF(v.width(), v.height()));
    const double extent = std::max({std::abs(topLeft.x()), std::abs(topLeft.y()), std::abs(bottomRight.x()),
                                    std::abs(bottomRight.y())});
    REQUIRE(work.maxCoord <= extent * 1.2 + 2.0);
    REQUIRE(work.length <= 20.0 * 2.0 * (v.width() + v.height()));

    // The event loop's longest gap while stepping, playing, switching heatmaps and
    // choosing rows (reported, not asserted: the machine may be loaded)
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0, worst = 0;
    int ticks = 0;
    QTimer probe;
    probe.setInterval(5);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.elapsed();
        worst = std::max(worst, now - last);
        last = now;
        ++ticks;
    });
    probe.start();
    auto spin = [&] {
        for (int i = 0; i < 3; ++i) QApplication::processEvents(QEventLoop::AllEvents, 10);
    };
    last = clock.elapsed();
    for (int i = 0; i < 20; ++i) {
        f.w.stepRay();
        spin();
    }
    for (Heatmap h : {Heatmap::Tests, Heatmap::HitMiss, Heatmap::VisitOrder, Heatmap::BeamNode, Heatmap::None}) {
        f.w.setHeatmap(h);
        spin();
    }
    const int events = int(f.state().recorder().events().size());
    for (int e : {events - 1, events / 2, 0}) {
        REQUIRE(f.w.selectEvent(e));
        spin();
    }
    f.w.setPlaying(true);
    for (int i = 0; i < 10; ++i) spin();
    f.w.setPlaying(false);
    probe.stop();
    WARN("stall probe: worst event-loop gap " << worst << " ms over " << ticks << " ticks");
    REQUIRE(ticks > 0);
    const PaintWork& after = f.w.overlayPainter().lastWork();
    REQUIRE(after.length <= 20.0 * 2.0 * (v.width() + v.height()));
}

TEST_CASE("A ray that hit nothing has no hull, blockers or target outlined", "[gui][clip][focus]") {
    Window f("pair");
    // Find an eye ray that hit nothing and put it in focus
    int miss = -1;
    for (int i = 0; i < 100000 && miss < 0; ++i) {
        REQUIRE(f.state().step());
        const auto& e = f.state().recorder().lastEvent();
        if (!e->deferred && e->task.node == 0 && e->lookup.known && e->lookup.answer().object < 0)
            miss = int(f.state().recorder().events().size()) - 1;
    }
    REQUIRE(miss >= 0);
    Overlays hull;
    hull.hull = true;
    hull.legend = false;
    f.w.setOverlays(hull);
    f.paint();
    // At most the empty cone of eye rays: no hull, origin, blocker or target outline
    REQUIRE(f.w.overlayPainter().lastWork().outlines <= 1);
    REQUIRE(f.errors.isEmpty());
}

TEST_CASE("Focus rules: the selected ray, else the selected pixel's eye ray, else the ray being traced", "[gui][focus]") {
    Window f("pair", rc::CacheKind::Blocker, rc::OrderKind::Scanline);
    // Trace until some ray below an eye ray was traced
    for (int i = 0; i < 200000; ++i) {
        REQUIRE(f.state().step());
        const auto& e = f.state().recorder().lastCommitted();
        if (i > 100 && e && e->task.node != 0) break;
    }
    f.w.stepRay();
    // Nothing selected: the ray being traced
    auto focus = rc::RayFocus::of(f.state(), f.w.selection());
    REQUIRE(focus);
    REQUIRE_FALSE(focus->selected);
    REQUIRE(focus->event == int(f.state().recorder().events().size()) - 1);
    // A pixel: its eye ray, and it stays in focus while tracing goes on
    const int w = f.state().width();
    const int pixel = f.state().recorder().events()[100].pixel;
    f.w.selectPixel(pixel % w, pixel / w);
    for (int i = 0; i < 50; ++i) f.w.stepRay();
    focus = rc::RayFocus::of(f.state(), f.w.selection());
    REQUIRE(focus);
    REQUIRE(focus->selected);
    REQUIRE(focus->pixel == pixel);
    REQUIRE(focus->node == 0);
    // A deeper ray of a pixel (what a ray-tree row gives)
    int deep = -1;
    for (std::size_t i = 0; i < f.state().recorder().events().size() && deep < 0; ++i)
        if (f.state().recorder().events()[i].node != 0 && !f.state().recorder().events()[i].deferred()) deep = int(i);
    REQUIRE(deep >= 0);
    REQUIRE(f.w.selectEvent(deep));
    focus = rc::RayFocus::of(f.state(), f.w.selection());
    REQUIRE(focus);
    REQUIRE(focus->event == deep);
    REQUIRE(focus->pixel == f.state().recorder().events()[std::size_t(deep)].pixel);
    // The same ray reached through --select x,y:path
    const rc::EventRecord& r = f.state().recorder().events()[std::size_t(deep)];
    const QString path = QString::fromStdString(f.state().session().cacheTree().label(r.node));
    QString why;
    REQUIRE(f.w.selectRay(r.pixel % w, r.pixel / w, path, why));
    REQUIRE(rc::RayFocus::of(f.state(), f.w.selection())->node == r.node);
    REQUIRE_FALSE(f.w.selectRay(r.pixel % w, r.pixel / w, "eye/sideways", why));
    REQUIRE(why.contains("eye/sideways"));
    REQUIRE_FALSE(f.w.selectRay(100000, 0, "", why));
    // Out-of-range events are refused, not read
    REQUIRE_FALSE(f.w.selectEvent(-5));
    REQUIRE_FALSE(f.w.selectEvent(int(f.state().recorder().events().size())));
    REQUIRE_FALSE(rc::RayFocus::ofEvent(f.state(), int(f.state().recorder().events().size())));
    // An untraced pixel: nothing in focus
    f.w.selectPixel(w - 1, f.state().height() - 1);
    REQUIRE_FALSE(rc::RayFocus::of(f.state(), f.w.selection()));
}

TEST_CASE("The options select X Y PATH and accel parse and bad ones are errors", "[gui][cli][focus]") {
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui", "--select", "3,4:eye/reflection", "--accel", "bvh"}, o, msg) == ParseResult::Ok);
    REQUIRE(o.select == QPoint(3, 4));
    REQUIRE(o.selectPath == "eye/reflection");
    REQUIRE(o.accel == rc::AccelKind::Bvh);
    GuiOptions bad;
    REQUIRE(parseGuiOptions({"raycache-gui", "--select", "3,4:"}, bad, msg) == ParseResult::Error);
    REQUIRE(parseGuiOptions({"raycache-gui", "--select", "3;4"}, bad, msg) == ParseResult::Error);
    REQUIRE(parseGuiOptions({"raycache-gui", "--accel", "kdtree"}, bad, msg) == ParseResult::Error);
    REQUIRE(msg.contains("--accel"));
}

TEST_CASE("Go to step moves forwards and backwards to the render as it was", "[gui][step]") {
    Window f("pair");
    f.w.goToStep(500);
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 500);
    const QImage at500 = SessionController::imageOf(f.state());
    f.w.goToStep(800);
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 800);
    REQUIRE(SessionController::imageOf(f.state()) != at500);
    f.w.goToStep(500);
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 500);
    REQUIRE(SessionController::imageOf(f.state()) == at500);
}

TEST_CASE("wait() runs no event loop, so it cannot be re-entered", "[gui][worker]") {
    Window f("cube:4", rc::CacheKind::None, rc::OrderKind::Scanline);
    bool delivered = false;
    QTimer::singleShot(0, [&] { delivered = true; });  // stands for a user's click
    bool finished = false;
    QObject::connect(&f.w.controller(), &SessionController::finished, [&] { finished = true; });
    REQUIRE(f.w.controller().start(rc::RunGoal::ToStep, 2000));
    f.w.controller().wait();
    REQUIRE_FALSE(f.w.controller().busy());
    REQUIRE(finished);          // the state was handed back
    REQUIRE_FALSE(delivered);   // and nothing else ran meanwhile
    REQUIRE(f.state().session().steps() == 2000);
    f.w.controller().wait();    // a second wait is a no-op
    QApplication::processEvents();
    REQUIRE(delivered);
    REQUIRE(f.state().session().steps() == 2000);  // the late hand-back changed nothing
}

TEST_CASE("Each render state has its own serial, so derived layers never go stale", "[gui][worker]") {
    Window f("pair");
    const std::uint64_t before = f.state().serial();
    for (int i = 0; i < 10; ++i) f.w.stepRay();
    f.w.stepBack();
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 9);
    REQUIRE(f.state().serial() != before);
}

TEST_CASE("With no arguments the window opens on a partly traced image with a hit ray's hull in focus", "[gui][first]") {
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui"}, o, msg) == ParseResult::Ok);
    REQUIRE(o.firstImpression);
    REQUIRE((o.overlays.hull && o.overlays.frontier));
    GuiOptions given;
    REQUIRE(parseGuiOptions({"raycache-gui", "pair"}, given, msg) == ParseResult::Ok);
    REQUIRE_FALSE(given.firstImpression);

    MainWindow w;
    QString errText;
    QTextStream err(&errText);
    REQUIRE(applyOptions(w, o, err));
    const rc::SessionState* s = w.controller().state();
    REQUIRE(s != nullptr);
    // Partly traced: some pixels visited, not all
    int visited = 0;
    for (int px = 0; px < s->width() * s->height(); ++px) visited += s->recorder().firstVisit(px) >= 0;
    REQUIRE(visited > s->width() * s->height() / 5);
    REQUIRE(visited < s->width() * s->height());
    // A hit ray in focus whose hull holds potential blockers
    const auto f = rc::RayFocus::of(*s, w.selection());
    REQUIRE(f);
    REQUIRE(f->selected);
    REQUIRE(f->hit >= 0);
    const rc::BlockerLists* lists = s->session().strategy().blockerLists();
    REQUIRE(lists != nullptr);
    const std::vector<int>* blockers = lists->find(lists->originSite(f->origin), f->hit);
    REQUIRE(blockers != nullptr);
    REQUIRE_FALSE(blockers->empty());
}

TEST_CASE("The Scene menu lists cube:N and balls:N sizes and every scene in scenes/", "[gui][scene]") {
    MainWindow w;
    const QStringList choices = w.sceneChoices();
    for (const char* c : {"cube:2", "cube:4", "cube:8", "balls:1", "balls:4", "pair", "glass"})
        REQUIRE(choices.contains(c));
    // Each :N scene offers its own sizes: none beyond balls:N's limit
    for (const QString& c : choices)
        if (c.startsWith("balls:")) REQUIRE(c.mid(6).toInt() <= rc::kMaxSphereflake);
    const QStringList files = QDir(RAYCACHE_SCENES_DIR).entryList({"*.nff"}, QDir::Files);
    REQUIRE(files.size() >= 5);
    for (const QString& file : files) REQUIRE(choices.contains(file));
}

TEST_CASE("A bad --select or --accel keeps the scene and says why", "[gui][cli]") {
    GuiOptions o;
    o.scene = "pair";
    o.steps = 10;
    o.select = QPoint(5000, 5);
    MainWindow w;
    QString errText;
    QTextStream err(&errText);
    REQUIRE_FALSE(applyOptions(w, o, err));
    REQUIRE(errText.contains("--select"));
    REQUIRE(errText.contains("outside"));
    REQUIRE(w.scene() != nullptr);
    REQUIRE(w.scene()->name == "pair");
}

TEST_CASE("The key sits beside the image when there is room, presentation mode hides the panels", "[gui][layout]") {
    Window f("pair");
    // 2000 rays traced (on the worker: stepping them one by one repaints the window each time)
    f.w.goToStep(2000);
    f.w.controller().wait();
    REQUIRE(f.state().session().steps() == 2000);
    f.w.setOverlays(*Overlays::parse("all"));
    f.w.setHeatmap(Heatmap::Tests);
    f.w.setPresentation(true);
    f.w.resize(2400, 900);
    QApplication::processEvents();
    f.w.imageView()->fit();
    f.paint();
    const ImageView& v = *f.w.imageView();
    const QRectF image(v.imageToWidget(QPointF(0, 0)), v.imageToWidget(QPointF(v.image().width(), v.image().height())));
    const QRectF key = f.w.overlayPainter().legendKey();
    REQUIRE(!key.isEmpty());
    REQUIRE_FALSE(key.intersects(image));
    REQUIRE_FALSE(f.w.rayTreePanel()->isVisible());
    REQUIRE(f.w.overlays().lineScale > 1.0);  // presentation uses large fonts and thicker lines
    f.w.setPresentation(false);
    QApplication::processEvents();
    REQUIRE(f.w.rayTreePanel()->isVisible());
    REQUIRE(f.w.overlays().lineScale == 1.0);
}

TEST_CASE("Hovering a pixel tells its tests, hits and misses", "[gui][layout]") {
    Window f("pair", rc::CacheKind::Blocker, rc::OrderKind::Scanline);
    f.w.goToStep(3000);
    f.w.controller().wait();
    const rc::SessionState& s = f.state();
    REQUIRE(s.session().steps() == 3000);
    const int px = s.recorder().events()[10].pixel;
    const QString tip = f.w.imageView()->tooltipAt(px % s.width(), px / s.width());
    REQUIRE(tip.contains(QString("%1 tests").arg(s.recorder().testsAt(px))));
    REQUIRE(tip.contains(QString("%1 hits").arg(s.recorder().hitsAt(px))));
    REQUIRE(tip.contains(QString("%1 misses").arg(s.recorder().missesAt(px))));
    REQUIRE(f.w.imageView()->tooltipAt(s.width() - 1, s.height() - 1).contains("not traced"));
    REQUIRE(f.w.imageView()->tooltipAt(-1, 0).isEmpty());
}

TEST_CASE("The record option writes a numbered PNG sequence of the fill", "[gui][screenshot]") {
    QTemporaryDir dir;
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui", "fill", "--record", dir.filePath("seq"), "--every", "1500", "--overlays", "all",
                             "--window", "640x480"}, o, msg) == ParseResult::Ok);
    REQUIRE(o.every == 1500);
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    REQUIRE(recordSequence(o, out, err) == 0);
    const QStringList frames = QDir(dir.filePath("seq")).entryList({"frame_*.png"}, QDir::Files, QDir::Name);
    // fill is 64x64: its rays come to a few thousand, so a handful of frames, the last complete
    REQUIRE(frames.size() >= 2);
    REQUIRE(frames.front() == "frame_00000.png");
    REQUIRE(outText.contains(QString("wrote %1 frames").arg(frames.size())));
    const QImage first(dir.filePath("seq/" + frames.front())), last(dir.filePath("seq/" + frames.back()));
    REQUIRE(!first.isNull());
    REQUIRE(first != last);
    GuiOptions bad;
    REQUIRE(parseGuiOptions({"raycache-gui", "--every", "0"}, bad, msg) == ParseResult::Error);
}
