#include "gui_options.h"

#include <cmath>

#include <QCommandLineParser>

#include "labels.h"
#include "order/order_registry.h"
#include "scene/nff_reader.h"
#include "search/search_registry.h"

namespace rcgui {

namespace {
// cube:4 at 512x512, breadth-first: about half the image traced
constexpr qint64 kFirstImpressionSteps = 150000;
bool parseInt(const QString& s, int lo, int hi, int& out) {
    bool ok = false;
    const int v = s.toInt(&ok);
    if (!ok || v < lo || v > hi) return false;
    out = v;
    return true;
}
bool parsePair(const QString& s, QChar sep, int& a, int& b) {
    const QStringList parts = s.split(sep);
    return parts.size() == 2 && parseInt(parts[0], 0, 100000, a) && parseInt(parts[1], 0, 100000, b);
}
/// Every cache's name, in the order tables list them
QStringList cacheNames() {
    QStringList out;
    for (rc::CacheKind k : rc::allCacheKinds()) out << text(rc::toString(k));
    return out;
}
/// Every order's name (rc::orderRegistry)
QStringList orderNames() {
    QStringList out;
    for (const std::string& n : rc::orderRegistry().names()) out << text(n);
    return out;
}
/// Every exact complete search's name (rc::searchRegistry; not Embree's, for comparison only)
QStringList searchNames() {
    QStringList out;
    for (const rc::SearchInfo& s : rc::searchRegistry().entries())
        if (!s.comparisonOnly) out << text(s.name);
    return out;
}
constexpr int kMaxSize = int(rc::NffLimits::maxResolution);
/// Every miss reason's name (rc::MissReason from Cold on)
QStringList missReasonNames() {
    QStringList out;
    for (int i = 1; i < rc::kMissReasons; ++i) out << text(rc::toString(rc::MissReason(i)));
    return out;
}
/// "a, b or c"
QString oneOf(QStringList names) {
    const QString last = names.takeLast();
    return names.join(", ") + " or " + last;
}
}  // namespace

std::optional<CompareChoice> parseCompare(const QString& spec, QString& error) {
    const QStringList parts = spec.trimmed().toLower().split(':');
    const auto cache = rc::parseCacheKind(parts[0].toStdString());
    const auto order = parts.size() == 2 ? rc::parseOrderKind(parts[1].toStdString()) : std::nullopt;
    if (parts.size() != 2 || !cache || !order) {
        error = "--compare must be CACHE:ORDER, with CACHE " + oneOf(cacheNames()) +
                " and ORDER " + oneOf(orderNames()) + " (e.g. none:scanline), not '" + spec + "'";
        return std::nullopt;
    }
    return CompareChoice{*cache, *order};
}

QString toString(const CompareChoice& c) {
    return QString("%1:%2").arg(QString::fromUtf8(rc::toString(c.cache).data()),
                                QString::fromUtf8(rc::toString(c.order).data()));
}

QString toString(SceneAngle a) {
    switch (a) {
        case SceneAngle::Side: return "side";
        case SceneAngle::Along: return "along";
        case SceneAngle::Top: return "top";
        case SceneAngle::Front: return "front";
    }
    return "side";
}

const QStringList& panelNames() {
    static const QStringList names{"ray-tree", "cache-tree", "statistics", "event-log", "objects"};
    return names;
}

std::optional<SceneAngle> parseSceneAngle(const QString& s) {
    for (SceneAngle a : {SceneAngle::Side, SceneAngle::Along, SceneAngle::Top, SceneAngle::Front})
        if (s.trimmed().toLower() == toString(a)) return a;
    return std::nullopt;
}

ParseResult parseGuiOptions(const QStringList& args, GuiOptions& out, QString& message) {
    // Declare the options, in the groups the help lists
    QCommandLineParser p;
    p.setApplicationDescription(
        "RayCache: step through ray tracing ray by ray, with Hanrahan's (1986) blocker lists,\n"
        "Speer-DeRose-Barsky cylinders of safety and the breadth-first frontier drawn on the image.\n"
        "With no display (and no QT_QPA_PLATFORM), renders headless to a PNG and exits.");
    p.addPositionalArgument("scene", "an .nff file or a built-in such as cube:4 (default cube:4)", "[scene]");
    const QCommandLineOption help({"h", "help"}, "Show this help.");
    const QCommandLineOption cache("cache", cacheNames().join(" | ") + " (default blocker)", "kind");
    const QCommandLineOption order("order", orderNames().join(" | ") + " (default bfs)", "kind");
    const QCommandLineOption width("width", "image width (default: the scene's)", "W");
    const QCommandLineOption height("height", "image height (default: the scene's)", "H");
    const QCommandLineOption steps("steps", "rays to trace before showing (screenshots: default 20000)", "N");
    const QCommandLineOption overlays("overlays", "cylinder,cone,frontier,misses,samples (or all, none, grid)", "list");
    const QCommandLineOption heatmap("heatmap", "none | tests | hitmiss | hitrate | order | beam", "mode");
    const QCommandLineOption screenshot("screenshot", "write the window to this PNG and exit", "file");
    const QCommandLineOption window("window", "window size of screenshots (default 1600x1000)", "WxH");
    const QCommandLineOption select("select", "pixel to inspect, and which of its rays (a path such as eye/reflection/shadow 1; default its eye ray)", "x,y[:path]");
    const QCommandLineOption accel("accel", searchNames().join(" | ") + ": what answers complete searches (default linear)", "kind");
    const QCommandLineOption band("band", "breadth-first and progressive orders: scanlines per band, 0 for the whole image (default: by cache and search, as raycache render)", "N");
    const QCommandLineOption zoom("zoom", "screenshots: zoom factor (relative to fitting the window) about the ray being traced, or the selected pixel", "F");
    const QCommandLineOption record("record", "write a numbered PNG sequence of the fill (overlays on) to this folder, then exit", "dir");
    const QCommandLineOption every("every", "--record: steps between frames (default 10000)", "N");
    const QCommandLineOption large("large-fonts", "bigger text, for a projector");
    const QCommandLineOption present("present", "presentation mode: the panels hidden, large fonts (F11 in the window)");
    const QCommandLineOption compare("compare", "run a second render (another cache and order) in lockstep beside the first, e.g. none:scanline", "cache:order");
    const QCommandLineOption sceneView("scene-view", "show the 3D scene beside the image: side (across the ray in focus, the paper's Figure 2), along (down the ray, Figure 1), top or front", "angle");
    const QCommandLineOption orbit("orbit", "--scene-view: turn the view by YAW and PITCH degrees", "yaw,pitch");
    // Distributed ray tracing, as `raycache render` takes it
    const QCommandLineOption spp("spp", "pixel samples, stratified and jittered (default 1)", "N");
    const QCommandLineOption lightRadius("light-radius", "lights become spheres of this radius (default 0)", "R");
    const QCommandLineOption shadowSamples("shadow-samples", "shadow rays per light and hit when --light-radius > 0", "K");
    const QCommandLineOption gloss("gloss", "half-angle in degrees of the cone of glossy reflections (default 0)", "DEG");
    const QCommandLineOption glossSamples("gloss-samples", "reflection rays per hit when --gloss > 0", "K");
    const QCommandLineOption seed("seed", "seed of distributed ray tracing's samples (default 1986)", "S");
    // Lectures
    const QCommandLineOption tour("tour", "open a tour: a JSON file of stops, each a caption and what to show (PageDown/PageUp move)", "file");
    const QCommandLineOption stop("stop", "--tour: the stop to open on, from 1 (default 1)", "K");
    const QCommandLineOption focus("focus", "fit the view to this image rectangle, in pixels", "x0,y0,x1,y1");
    const QCommandLineOption missReason("miss-reason", "Next miss stops only at misses of this reason (" + missReasonNames().join(", ") + ")", "reason");
    const QCommandLineOption frameLog("frame-log", "write one line per UI-thread task, NAME MILLISECONDS, to this file", "file");
    const QCommandLineOption panels("panels", "the panels to show: " + panelNames().join(", ") + ", all or none", "list");
    const QCommandLineOption run("run", "after --steps, trace on to the next-miss (of --miss-reason, if given) or next-deferral, and focus on it", "goal");
    const QCommandLineOption walk("walk", "quit once shown (with --tour: show every stop from --stop on in turn, then quit): for --frame-log");
    for (const auto& o : {help, cache, order, width, height, steps, overlays, heatmap, screenshot, window, select, accel, band, record, every, zoom, large,
                          present, compare, sceneView, orbit, spp, lightRadius, shadowSamples, gloss, glossSamples, seed,
                          tour, stop, focus, missReason, frameLog, panels, run, walk})
        p.addOption(o);
    // --scene-view may come alone (the side view): give it its default value
    QStringList argv = args;
    for (int i = 1; i < argv.size(); ++i)
        if (argv[i] == "--scene-view" && (i + 1 == argv.size() || !parseSceneAngle(argv[i + 1])))
            argv[i] = "--scene-view=side";
    if (!p.parse(argv)) {
        message = p.errorText();
        return ParseResult::Error;
    }
    if (p.isSet(help)) {
        message = p.helpText();
        return ParseResult::Help;
    }
    // Lectures: the tour and its stop, the frame log, the goal to run to, the panels, the focus
    if (args.size() <= 1 || p.isSet(tour)) {
        if (p.isSet(tour)) out.tour = p.value(tour);
        if (p.isSet(stop) && (!p.isSet(tour) || !parseInt(p.value(stop), 1, 100000, out.stop))) {
            message = p.isSet(tour) ? "--stop must be a stop number from 1" : "--stop needs --tour";
            return ParseResult::Error;
        }
    }
    if (p.isSet(frameLog)) out.frameLog = p.value(frameLog);
    out.walk = p.isSet(walk);
    if (p.isSet(run)) {
        const QString v = p.value(run).trimmed().toLower();
        if (v == "next-miss") out.runTo = rc::RunGoal::NextMiss;
        else if (v == "next-deferral") out.runTo = rc::RunGoal::NextDeferral;
        else { message = "--run must be next-miss or next-deferral, not '" + p.value(run) + "'"; return ParseResult::Error; }
    }
    if (p.isSet(panels)) {
        const QString v = p.value(panels).trimmed().toLower();
        QStringList shown;
        if (v == "all") shown = panelNames();
        else if (v != "none")
            for (const QString& name : v.split(',')) {
                if (!panelNames().contains(name.trimmed())) {
                    message = "--panels takes a comma-separated list of " + panelNames().join(", ") + ", or all or none, not '" + name + "'";
                    return ParseResult::Error;
                }
                shown << name.trimmed();
            }
        out.panels = shown;
    }
    if (p.isSet(focus)) {
        const QStringList c = p.value(focus).split(',');
        int v[4] = {0, 0, 0, 0};
        bool ok = c.size() == 4;
        for (int i = 0; ok && i < 4; ++i) ok = parseInt(c[i].trimmed(), 0, kMaxSize, v[i]);
        if (!ok || v[2] <= v[0] || v[3] <= v[1]) {
            message = "--focus must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not '" + p.value(focus) + "'";
            return ParseResult::Error;
        }
        out.focus = QRect(QPoint(v[0], v[1]), QPoint(v[2] - 1, v[3] - 1));
    }
    if (p.isSet(missReason)) {
        const QStringList names = missReasonNames();
        const int i = int(names.indexOf(p.value(missReason).trimmed().toLower()));
        if (i < 0) { message = "--miss-reason must be " + oneOf(names) + ", not '" + p.value(missReason) + "'"; return ParseResult::Error; }
        out.missReason = rc::MissReason(i + 1);
    }
    // No arguments: the first impression
    if (args.size() <= 1) {
        out.firstImpression = true;
        out.steps = kFirstImpressionSteps;
        out.overlays = *Overlays::parse("cylinder,cone,frontier");
    }
    // The scene
    const QStringList pos = p.positionalArguments();
    if (pos.size() > 1) {
        message = "only one scene may be given";
        return ParseResult::Error;
    }
    if (pos.size() == 1) {
        out.scene = pos[0];
        out.sceneGiven = true;
    }
    // What renders: cache, order, image size, steps
    if (p.isSet(cache)) {
        const auto k = rc::parseCacheKind(p.value(cache).toStdString());
        if (!k) { message = "--cache must be " + oneOf(cacheNames()) + ", not '" + p.value(cache) + "'"; return ParseResult::Error; }
        out.cache = *k;
    }
    if (p.isSet(order)) {
        const auto k = rc::parseOrderKind(p.value(order).toStdString());
        if (!k) { message = "--order must be " + oneOf(orderNames()) + ", not '" + p.value(order) + "'"; return ParseResult::Error; }
        out.order = *k;
    }
    // The command line's limit (rc::NffLimits::maxResolution), not one of the GUI's own
    const QString sizeRange = QString("[1, %1]").arg(kMaxSize);
    if (p.isSet(width) && !parseInt(p.value(width), 1, kMaxSize, out.width)) { message = "--width must be an integer in " + sizeRange; return ParseResult::Error; }
    if (p.isSet(height) && !parseInt(p.value(height), 1, kMaxSize, out.height)) { message = "--height must be an integer in " + sizeRange; return ParseResult::Error; }
    if (p.isSet(steps)) {
        bool ok = false;
        out.steps = p.value(steps).toLongLong(&ok);
        if (!ok || out.steps < 0) { message = "--steps must be a non-negative integer"; return ParseResult::Error; }
    }
    // What is drawn: overlays and heatmap
    if (p.isSet(overlays)) {
        const auto o = Overlays::parse(p.value(overlays));
        if (!o) { message = "--overlays takes a comma-separated list of cylinder, cone, frontier, misses, samples, grid, all, none"; return ParseResult::Error; }
        out.overlays = *o;
    }
    if (p.isSet(heatmap)) {
        const auto h = parseHeatmap(p.value(heatmap));
        if (!h) { message = "--heatmap must be none, tests, hitmiss, hitrate, order or beam"; return ParseResult::Error; }
        out.heatmap = *h;
    }
    // Screenshots and recordings
    if (p.isSet(screenshot)) out.screenshot = p.value(screenshot);
    if (p.isSet(record)) out.record = p.value(record);
    if (p.isSet(every)) {
        bool ok = false;
        out.every = p.value(every).toLongLong(&ok);
        if (!ok || out.every < 1) { message = "--every must be a positive integer"; return ParseResult::Error; }
    }
    if (p.isSet(window)) {
        int w = 0, h = 0;
        if (!parsePair(p.value(window).toLower(), 'x', w, h) || w < 200 || h < 200) { message = "--window must be WxH, at least 200x200"; return ParseResult::Error; }
        out.window = QSize(w, h);
    }
    // The pixel and ray in focus, the complete search, the zoom
    if (p.isSet(select)) {
        int x = 0, y = 0;
        QString v = p.value(select);
        const int colon = int(v.indexOf(':'));
        if (colon >= 0) {
            out.selectPath = v.mid(colon + 1).trimmed();
            v = v.left(colon);
            if (out.selectPath.isEmpty()) { message = "--select x,y:path needs a path after ':' (e.g. eye/reflection)"; return ParseResult::Error; }
        }
        if (!parsePair(v, ',', x, y)) { message = "--select must be x,y or x,y:path, not '" + p.value(select) + "'"; return ParseResult::Error; }
        out.select = QPoint(x, y);
    }
    if (p.isSet(accel)) {
        const auto k = rc::parseAccelKind(p.value(accel).toStdString());
        if (!k || rc::searchRegistry()[std::size_t(*k)].comparisonOnly) { message = "--accel must be " + oneOf(searchNames()) + ", not '" + p.value(accel) + "'"; return ParseResult::Error; }
        out.accel = *k;
    }
    if (p.isSet(band) && !parseInt(p.value(band), 0, 100000, out.band)) {
        message = "--band must be a whole number of scanlines >= 0 (0: the whole image), not '" + p.value(band) + "'";
        return ParseResult::Error;
    }
    if (p.isSet(zoom)) {
        bool ok = false;
        out.zoom = p.value(zoom).toDouble(&ok);
        if (!ok || out.zoom < 0.1 || out.zoom > 200) { message = "--zoom must be a number in [0.1, 200]"; return ParseResult::Error; }
    }
    // Presentation, the compared render, the scene view
    out.largeFonts = p.isSet(large);
    out.present = p.isSet(present);
    if (p.isSet(compare)) {
        out.compare = parseCompare(p.value(compare), message);
        if (!out.compare) return ParseResult::Error;
    }
    if (p.isSet(sceneView)) {
        const auto a = parseSceneAngle(p.value(sceneView));
        if (!a) { message = "--scene-view must be side, along, top or front, not '" + p.value(sceneView) + "'"; return ParseResult::Error; }
        out.sceneView = true;
        out.sceneAngle = *a;
    }
    if (p.isSet(orbit)) {
        const QStringList parts = p.value(orbit).split(',');
        bool ok1 = false, ok2 = false;
        if (parts.size() == 2) {
            out.orbitYaw = parts[0].toDouble(&ok1);
            out.orbitPitch = parts[1].toDouble(&ok2);
        }
        if (!ok1 || !ok2 || std::abs(out.orbitYaw) > 360 || std::abs(out.orbitPitch) > 90) {
            message = "--orbit must be YAW,PITCH in degrees (|yaw| <= 360, |pitch| <= 90), not '" + p.value(orbit) + "'";
            return ParseResult::Error;
        }
    }
    // Distributed ray tracing: the core's own check, so the limits are the CLI's
    auto number = [&](const QCommandLineOption& o, double& v) {
        if (!p.isSet(o)) return true;
        bool ok = false;
        v = p.value(o).toDouble(&ok);
        if (!ok) message = "--" + o.names().front() + " must be a number, not '" + p.value(o) + "'";
        return ok;
    };
    auto count = [&](const QCommandLineOption& o, int& v) {
        if (!p.isSet(o)) return true;
        bool ok = false;
        v = p.value(o).toInt(&ok);
        if (!ok) message = "--" + o.names().front() + " must be a whole number, not '" + p.value(o) + "'";
        return ok;
    };
    rc::Sampling& sm = out.sampling;
    if (!count(spp, sm.spp) || !number(lightRadius, sm.lightRadius) || !count(shadowSamples, sm.shadowSamples) ||
        !number(gloss, sm.glossDegrees) || !count(glossSamples, sm.glossSamples))
        return ParseResult::Error;
    if (p.isSet(seed)) {
        bool ok = false;
        sm.seed = p.value(seed).toULongLong(&ok);
        if (!ok) { message = "--seed must be a whole number >= 0"; return ParseResult::Error; }
    }
    if (const auto e = rc::samplingError(sm, rc::ShadingOptions{}.maxDepth)) {
        message = QString::fromStdString(*e);
        return ParseResult::Error;
    }
    return ParseResult::Ok;
}

std::optional<GuiOptions> stopOptions(const rc::Tour& tour, int stop, const GuiOptions& base, QString& message) {
    const rc::TourStop& st = tour.stops.at(std::size_t(stop - 1));
    // The stop's settings as flags, the scene as the positional argument
    QStringList args{"raycache-gui"};
    for (const rc::TourSetting& s : st.settings) {
        if (s.key == "scene") {
            args << QString::fromStdString(rc::stopScene(tour, st));  // a relative path: beside the tour
            continue;
        }
        args << "--" + QString::fromStdString(s.key);
        if (!s.value.empty()) args << QString::fromStdString(s.value);
    }
    GuiOptions o;
    QString why;
    if (parseGuiOptions(args, o, why) != ParseResult::Ok) {
        message = QString("%1:%2:%3: stop %4 (%5): %6")
                      .arg(QString::fromStdString(tour.file)).arg(st.line).arg(st.column).arg(stop)
                      .arg(QString::fromStdString(st.title), why);
        return std::nullopt;
    }
    // A stop shows the panels it names, no others
    if (!o.panels) o.panels = QStringList();
    // What the command line chose for the whole run stays: window, fonts, outputs
    o.walk = base.walk;
    o.window = base.window;
    o.largeFonts = base.largeFonts;
    o.present = base.present;
    o.screenshot = base.screenshot;
    o.frameLog = base.frameLog;
    o.tour = base.tour;
    o.stop = stop;
    return o;
}

}  // namespace rcgui
