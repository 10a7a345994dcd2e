// GUI tests: the sample rays of the pixel in focus (distributed ray tracing's fan of
// shadow rays to the light's sphere) and the cache hit-rate heatmap.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include <QApplication>
#include <QProcess>
#include <QTextStream>

#include <glm/geometric.hpp>

#include "gui_options.h"
#include "heatmap_builder.h"
#include "image_view.h"
#include "main_window.h"
#include "window_fixture.h"
#include "palette.h"
#include "view/sample_fan.h"
#include "scene_view.h"
#include "screenshot.h"
#include "view/session_state.h"

using namespace rcgui;

namespace {

// A window on `scene` at 32 x 32 with the given options, run to step `steps`
struct SampledWindow {
    MainWindow w;
    explicit SampledWindow(QStringList args, qint64 steps = 1000000000) {
        GuiOptions o;
        QString msg;
        args = QStringList{"raycache-gui", "--width", "32", "--height", "32"} + args;
        REQUIRE(parseGuiOptions(args, o, msg) == ParseResult::Ok);
        o.steps = steps;
        QString errors;
        QTextStream err(&errors);
        REQUIRE(applyOptions(w, o, err));
        rcgui::testing::showAt(w, 1200, 900);
        w.imageView()->fit();
    }
    rc::SessionState& state() { return rcgui::testing::stateOf(w); }
};

const QStringList kSoft{"cube:4", "--cache", "blocker", "--order", "scanline", "--spp", "4", "--light-radius", "0.3",
                        "--shadow-samples", "8", "--seed", "7"};

}  // namespace

TEST_CASE("The fan of a pixel: spp eye samples, K shadow rays per lit hit, each ending in the light's sphere", "[gui][samples]") {
    SampledWindow f(kSoft);
    const rc::SessionState& s = f.state();
    REQUIRE(s.session().done());
    const rc::Scene& scene = s.session().scene();
    REQUIRE(scene.lights.size() >= 1);
    int fully = 0, partly = 0, blocked = 0;
    for (int px = 0; px < s.width() * s.height(); px += 7) {
        const rc::SampleFan fan = rc::SampleFan::trace(s.session(), px);
        INFO("pixel " << px);
        REQUIRE_FALSE(fan.cut);
        REQUIRE(fan.count(rc::RayKind::Primary) == 4);
        // The render traced these very rays: as many as the pixel's committed events
        int committed = 0;
        for (int i : s.recorder().eventsOf(px)) committed += s.recorder().events()[std::size_t(i)].deferred() ? 0 : 1;
        REQUIRE(int(fan.rays.size()) == committed);
        std::map<std::pair<int, int>, int> perHitAndLight;
        int hits = 0;
        for (const rc::FanRay& r : fan.rays) {
            if (r.kind != rc::RayKind::Shadow) {
                hits += r.hit >= 0 ? 1 : 0;
                continue;
            }
            ++perHitAndLight[{r.parent, r.light}];
            blocked += r.outcome == rc::FanOutcome::Blocked ? 1 : 0;
            // Every shadow ray goes to a point of its light's sphere; a lit one stops there
            const rc::Sphere& light = fan.lights[std::size_t(r.light)];
            REQUIRE(light.r == 0.3);
            REQUIRE(glm::length(r.aim - light.c) <= light.r * (1.0 + 1e-9));
            if (r.outcome == rc::FanOutcome::Lit) REQUIRE(glm::length(r.to - r.aim) <= 1e-9);
            else REQUIRE(glm::length(r.to - r.from) < glm::length(r.aim - r.from));
            REQUIRE(fan.rays[std::size_t(r.parent)].hit >= 0);
            REQUIRE(glm::length(fan.rays[std::size_t(r.parent)].to - r.from) <= 1e-9);
        }
        // Each hit sends K rays to each light, less those whose point is behind the surface
        int shadows = 0;
        for (const auto& [key, n] : perHitAndLight) {
            REQUIRE(n <= 8);
            shadows += n;
            // A light whose whole sphere lies on the lit side of the surface gets all K
            const rc::FanRay& hit = fan.rays[std::size_t(key.first)];
            const rc::Vec3 p = hit.to;
            rc::Vec3 normal = scene.normal(hit.hit, p);
            if (glm::dot(normal, hit.from - p) < 0.0) normal = -normal;
            const rc::Sphere& light = fan.lights[std::size_t(key.second)];
            if (glm::dot(light.c - p, normal) > light.r * 1.001) {
                REQUIRE(n == 8);
                ++fully;
            } else {
                ++partly;
            }
        }
        REQUIRE(shadows + fan.notCast == hits * int(scene.lights.size()) * 8);
    }
    WARN("hit-light pairs with the whole sphere lit: " << fully << ", partly: " << partly << "; blocked shadow rays: " << blocked);
    REQUIRE(fully > 0);
    REQUIRE(blocked > 0);
}

TEST_CASE("The samples overlay draws every ray of the fan, in the image and in the scene view", "[gui][samples][overlay]") {
    SampledWindow f(kSoft);
    f.w.setSceneView(true);
    Overlays o;
    o.samples = true;
    o.legend = true;
    f.w.setOverlays(o);
    f.w.selectPixel(16, 14);
    const rc::SessionState& s = f.state();
    const rc::SampleFan& fan = s.fan(14 * 32 + 16);
    REQUIRE(fan.count(rc::RayKind::Shadow) > 0);
    f.w.refresh();
    f.w.imageView()->grab();
    // The whole image is in view: every ray is drawn, eye samples as dots
    REQUIRE(f.w.overlayPainter().lastWork().samples == int(fan.rays.size()));
    // The scene view draws the same rays
    REQUIRE(f.w.sceneView()->sketch().fan.rays.size() == fan.rays.size());
    REQUIRE(f.w.sceneView()->grab().width() > 0);
    REQUIRE(f.w.sceneView()->caption().contains(QString("%1 shadow").arg(fan.count(rc::RayKind::Shadow))));
    // Off: nothing of it
    o.samples = false;
    f.w.setOverlays(o);
    f.w.imageView()->grab();
    REQUIRE(f.w.overlayPainter().lastWork().samples == 0);
    REQUIRE(f.w.sceneView()->sketch().fan.rays.empty());
}

TEST_CASE("A fan over the ray limit is cut, and what it draws stays in the view at any zoom", "[gui][samples][stall]") {
    // 16 samples, 64 shadow rays per hit and glossy branching: far more than kMaxRays
    SampledWindow f({"cube:4", "--spp", "16", "--light-radius", "0.5", "--shadow-samples", "64", "--gloss", "10",
                     "--gloss-samples", "4"},
                    20000);
    f.w.setOverlays(*Overlays::parse("all"));
    const rc::SessionState& s = f.state();
    // A pixel whose samples reach the limit (eye rays that hit a reflecting object)
    int px = -1;
    for (const rc::EventRecord& r : s.recorder().events())
        if (!r.deferred() && r.rayKind() == rc::RayKind::Primary && r.hit >= 0 && rc::SampleFan::trace(s.session(), r.pixel).cut) {
            px = r.pixel;
            break;
        }
    REQUIRE(px >= 0);
    f.w.selectPixel(px % s.width(), px / s.width());
    const rc::SampleFan& fan = s.fan(px);
    REQUIRE(fan.cut);
    REQUIRE(int(fan.rays.size()) == rc::SampleFan::kMaxRays);
    f.w.setSceneView(true);
    REQUIRE(int(f.w.sceneView()->sketch().fan.rays.size()) == rc::SampleFan::kMaxRays);
    f.w.sceneView()->grab();
    REQUIRE(f.w.sceneView()->caption().contains(QString("the first %1").arg(rc::SampleFan::kMaxRays)));
    ImageView& v = *f.w.imageView();
    // Zoomed about the selected pixel, which stays at the middle of the view (about the
    // corner, what shows depends on where in the image the pixel is)
    const QPointF middle(v.width() / 2.0, v.height() / 2.0);
    const QPointF at(px % s.width() + 0.5, px / s.width() + 0.5);
    for (double zoom : {1.0, 400.0}) {
        const double z = v.zoom() * zoom;
        v.setZoom(z, middle - z * at);
        f.w.refresh();
        v.grab();
        const PaintWork& work = f.w.overlayPainter().lastWork();
        const QPointF topLeft = v.widgetToImage(QPointF(0, 0)), bottomRight = v.widgetToImage(QPointF(v.width(), v.height()));
        const double extent = std::max({std::abs(topLeft.x()), std::abs(topLeft.y()), std::abs(bottomRight.x()),
                                        std::abs(bottomRight.y())});
        INFO("zoom " << zoom);
        REQUIRE(work.samples > 0);
        REQUIRE(work.samples <= rc::SampleFan::kMaxRays);
        REQUIRE(work.maxCoord <= extent * 1.2 + 2.0);
        // Each segment is clipped to the view with its margin (5% and a pixel a side): at
        // most that rectangle's diagonal, in widget pixels
        const double w = bottomRight.x() - topLeft.x(), h = bottomRight.y() - topLeft.y();
        const double diagonal = std::hypot(w * 1.1 + 2.0, h * 1.1 + 2.0) * (v.width() / w);
        REQUIRE(work.sampleLength <= work.samples * diagonal);
    }
}

TEST_CASE("The hit-rate heatmap shows hits / (hits + misses) of each pixel's lookups, all its rays", "[gui][heatmap]") {
    SampledWindow f(kSoft, 60000);
    f.w.setHeatmap(Heatmap::HitRate);
    const rc::SessionState& s = f.state();
    const rc::TraceRecorder& rec = s.recorder();
    const int n = s.width() * s.height();
    // The pixel's lookups, counted from its recorded events
    std::vector<int> hits(std::size_t(n), 0), misses(std::size_t(n), 0);
    for (const rc::EventRecord& r : rec.events()) {
        if (r.deferred()) continue;
        hits[std::size_t(r.pixel)] += r.rayDecision() == rc::Decision::Hit ? 1 : 0;
        misses[std::size_t(r.pixel)] += r.rayDecision() == rc::Decision::Miss ? 1 : 0;
    }
    const QImage img = HeatmapBuilder::build(s, Heatmap::HitRate);
    std::uint64_t allHits = 0, allMisses = 0;
    int between = 0, traced = 0;
    for (int px = 0; px < n; ++px) {
        INFO("pixel " << px);
        REQUIRE(rec.hitsAt(px) == std::uint32_t(hits[std::size_t(px)]));
        REQUIRE(rec.missesAt(px) == std::uint32_t(misses[std::size_t(px)]));
        allHits += rec.hitsAt(px);
        allMisses += rec.missesAt(px);
        if (rec.firstVisit(px) < 0) {
            REQUIRE(img.pixelColor(px % s.width(), px / s.width()) == QColor(Qt::black));
            continue;
        }
        ++traced;
        const int h = hits[std::size_t(px)], m = misses[std::size_t(px)];
        REQUIRE(h + m > 0);  // the blocker cache looks every ray up
        const double rate = double(h) / double(h + m);
        REQUIRE(HeatmapBuilder::hitRate(s, px) == rate);
        REQUIRE(img.pixelColor(px % s.width(), px / s.width()) == palette::ramp(rate));
        between += rate > 0.0 && rate < 1.0 ? 1 : 0;
    }
    // ... and the pixels add up to the session's counters
    REQUIRE(allHits == s.session().counters().hits);
    REQUIRE(allMisses == s.session().counters().misses);
    REQUIRE(traced > 0);
    REQUIRE(between > 0);
    // The hover text says it
    int px = 0;
    while (rec.firstVisit(px) < 0) ++px;
    const QString tip = f.w.imageView()->tooltipAt(px % s.width(), px / s.width());
    REQUIRE(tip.contains(QString("hit rate %1%").arg(100.0 * *HeatmapBuilder::hitRate(s, px), 0, 'f', 1)));
    // The key's colour bar runs from 0 to 1 (100%)
    f.w.refresh();
    f.w.imageView()->grab();
    REQUIRE(f.w.overlayPainter().heatmapTop() == 1.0);
}

TEST_CASE("Without a cache the hit-rate heatmap says no lookups, not 0", "[gui][heatmap]") {
    SampledWindow f({"cube:3", "--cache", "none", "--spp", "2", "--light-radius", "0.3", "--shadow-samples", "2"}, 5000);
    f.w.setHeatmap(Heatmap::HitRate);
    const rc::SessionState& s = f.state();
    const QImage img = HeatmapBuilder::build(s, Heatmap::HitRate);
    int traced = 0;
    for (int px = 0; px < s.width() * s.height(); ++px) {
        if (s.recorder().firstVisit(px) < 0) continue;
        ++traced;
        REQUIRE_FALSE(HeatmapBuilder::hitRate(s, px).has_value());
        REQUIRE(img.pixelColor(px % s.width(), px / s.width()) == palette::kNoLookups);
    }
    REQUIRE(traced > 0);
    REQUIRE(palette::ramp(0.0) != palette::kNoLookups);
    const int px = s.recorder().events()[0].pixel;
    REQUIRE(f.w.imageView()->tooltipAt(px % s.width(), px / s.width()).contains("no cache lookups"));
}

TEST_CASE("The samples overlay and the hit-rate heatmap parse, and bad ones exit 2", "[gui][cli][samples]") {
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui", "--overlays", "samples", "--heatmap", "hitrate"}, o, msg) == ParseResult::Ok);
    REQUIRE(o.overlays.samples);
    REQUIRE_FALSE(o.overlays.hull);
    REQUIRE(o.heatmap == Heatmap::HitRate);
    REQUIRE(Overlays::parse("all")->samples);
    REQUIRE_FALSE(Overlays::parse("all,none")->samples);
    REQUIRE(parseGuiOptions({"raycache-gui", "--heatmap", "hit-rate"}, o, msg) == ParseResult::Error);
    REQUIRE(msg.contains("hitrate"));
    REQUIRE(parseGuiOptions({"raycache-gui", "--overlays", "samples,fans"}, o, msg) == ParseResult::Error);
    REQUIRE(msg.contains("samples"));
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    QProcess p;
    p.setProcessEnvironment(env);
    for (const QStringList& bad : {QStringList{"cube:2", "--heatmap", "rate", "--screenshot", "never.png"},
                                   QStringList{"cube:2", "--overlays", "fanz", "--screenshot", "never.png"}}) {
        p.start(RAYCACHE_GUI, bad);
        REQUIRE(p.waitForFinished(60000));
        REQUIRE(p.exitCode() == 2);
    }
}
