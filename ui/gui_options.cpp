#include "gui_options.h"

#include <cmath>

#include <algorithm>

#include "cli/flag_definitions.h"

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

namespace {

/// The command line's values as CLI11 reads them, before they become GuiOptions
struct Flags {
    std::vector<std::string> scenes;
    std::string cache, order, accel, overlays, heatmap, screenshot, window, select, record, compare, sceneView,
        orbit, tour, focus, missReason, frameLog, panels, run;
    int width = 0, height = 0, stop = 0, band = rc::kAutoBand;
    qint64 steps = -1, every = 10000;
    double zoom = 1.0;
    rc::Sampling sampling;
    bool large = false, present = false, walk = false, noAhead = false;
};

QString q(const std::string& s) { return QString::fromStdString(s); }

/// What renders: the options the CLI has too (cli/flag_definitions.h), then the GUI's own
void declareRender(CLI::App& app, Flags& f) {
    app.add_option("scene", f.scenes, "an .nff file or a built-in such as cube:4 (default cube:4)");
    rc::cli::addCacheOption(&app, f.cache);
    rc::cli::addOrderOption(&app, f.order);
    rc::cli::addAccelOption(&app, f.accel, true);
    rc::cli::addSizeOptions(&app, f.width, f.height);
    rc::cli::addBandOption(&app, f.band);
    rc::cli::addSamplingOptions(&app, f.sampling, true);
    app.add_option("--seed", f.sampling.seed, "seed of distributed ray tracing's samples (default 1986)");
    app.add_option("--steps", f.steps, "rays to trace before showing (screenshots: default 20000)")->check(CLI::NonNegativeNumber);
    app.add_option("--compare", f.compare, "run a second render (another cache and order) in lockstep beside the first, e.g. none:scanline");
}

/// What is drawn, and where it goes: overlays, heatmap, views, screenshots, fonts
void declareShow(CLI::App& app, Flags& f) {
    app.add_option("--overlays", f.overlays, "cylinder,cone,frontier,misses,samples (or all, none, grid)");
    app.add_option("--heatmap", f.heatmap, "none | tests | hitmiss | hitrate | order | beam");
    app.add_option("--screenshot", f.screenshot, "write the window to this PNG and exit");
    app.add_option("--window", f.window, "window size of screenshots (default 1600x1000)");
    app.add_option("--select", f.select, "pixel to inspect, and which of its rays (a path such as eye/reflection/shadow 1; default its eye ray): x,y[:path]");
    app.add_option("--zoom", f.zoom, "screenshots: zoom factor (relative to fitting the window) about the ray being traced, or the selected pixel")
        ->check(rc::cli::finiteNumber())->check(CLI::Range(0.1, 200.0));
    app.add_option("--record", f.record, "write a numbered PNG sequence of the fill (overlays on) to this folder, then exit");
    app.add_option("--every", f.every, "--record: steps between frames (default 10000)")->check(CLI::PositiveNumber);
    app.add_flag("--large-fonts", f.large, "bigger text, for a projector");
    app.add_flag("--present", f.present, "presentation mode: the panels hidden, large fonts (F11 in the window)");
    app.add_option("--scene-view", f.sceneView, "show the 3D scene beside the image: side (across the ray in focus, the paper's Figure 2), along (down the ray, Figure 1), top or front");
    app.add_option("--orbit", f.orbit, "--scene-view: turn the view by YAW,PITCH degrees");
}

/// Lectures: tours, their stops, the frame log
void declareLecture(CLI::App& app, Flags& f) {
    app.add_option("--tour", f.tour, "open a tour: a JSON file of stops, each a caption and what to show (PageDown/PageUp move)");
    app.add_option("--stop", f.stop, "--tour: the stop to open on, from 1 (default 1)")->check(CLI::Range(1, 100000));
    app.add_option("--focus", f.focus, "fit the view to this image rectangle, in pixels: x0,y0,x1,y1");
    app.add_option("--miss-reason", f.missReason, "Next miss stops only at misses of this reason (" + missReasonNames().join(", ").toStdString() + ")");
    app.add_option("--frame-log", f.frameLog, "write one line per UI-thread task, NAME MILLISECONDS, to this file (with a tour, also stop-K-picture: from a stop asked for to its picture complete)");
    app.add_option("--panels", f.panels, "the panels to show: " + panelNames().join(", ").toStdString() + ", all or none");
    app.add_option("--run", f.run, "after --steps, trace on to the next-miss (of --miss-reason, if given) or next-deferral, and focus on it");
    app.add_flag("--walk", f.walk, "quit once shown (with --tour: show every stop from --stop on in turn, then quit): for --frame-log");
    app.add_flag("--no-render-ahead", f.noAhead, "--tour: render each stop only when it is reached, not while the one before is shown");
}

/// The render's choices: the registered names the shared options checked
bool readRender(const Flags& f, GuiOptions& out, QString& message) {
    if (f.scenes.size() > 1) {
        message = "only one scene may be given";
        return false;
    }
    if (!f.scenes.empty()) {
        out.scene = q(f.scenes[0]);
        out.sceneGiven = true;
    }
    if (!f.cache.empty()) out.cache = *rc::parseCacheKind(f.cache);
    if (!f.order.empty()) out.order = *rc::parseOrderKind(f.order);
    if (!f.accel.empty()) out.accel = *rc::parseAccelKind(f.accel);
    out.width = f.width;
    out.height = f.height;
    out.band = f.band;
    if (f.steps >= 0) out.steps = f.steps;
    out.sampling = f.sampling;
    if (!f.compare.empty() && !(out.compare = parseCompare(q(f.compare), message))) return false;
    // What no single flag can check: the core's own, so the limits are the CLI's
    if (const auto e = rc::samplingError(out.sampling, rc::ShadingOptions{}.maxDepth)) {
        message = QString::fromStdString(*e);
        return false;
    }
    return true;
}

/// --select x,y or x,y:path
bool readSelect(const QString& v, GuiOptions& out, QString& message) {
    QString pixel = v;
    const int colon = int(v.indexOf(':'));
    if (colon >= 0) {
        out.selectPath = v.mid(colon + 1).trimmed();
        pixel = v.left(colon);
        if (out.selectPath.isEmpty()) {
            message = "--select x,y:path needs a path after ':' (e.g. eye/reflection)";
            return false;
        }
    }
    int x = 0, y = 0;
    if (!parsePair(pixel, ',', x, y)) {
        message = "--select must be x,y or x,y:path, not '" + v + "'";
        return false;
    }
    out.select = QPoint(x, y);
    return true;
}

/// --scene-view ANGLE and --orbit YAW,PITCH
bool readSceneView(const Flags& f, GuiOptions& out, QString& message) {
    if (!f.sceneView.empty()) {
        const auto a = parseSceneAngle(q(f.sceneView));
        if (!a) {
            message = "--scene-view must be side, along, top or front, not '" + q(f.sceneView) + "'";
            return false;
        }
        out.sceneView = true;
        out.sceneAngle = *a;
    }
    if (f.orbit.empty()) return true;
    const QStringList parts = q(f.orbit).split(',');
    bool ok1 = false, ok2 = false;
    if (parts.size() == 2) {
        out.orbitYaw = parts[0].toDouble(&ok1);
        out.orbitPitch = parts[1].toDouble(&ok2);
    }
    if (!ok1 || !ok2 || std::abs(out.orbitYaw) > 360 || std::abs(out.orbitPitch) > 90) {
        message = "--orbit must be YAW,PITCH in degrees (|yaw| <= 360, |pitch| <= 90), not '" + q(f.orbit) + "'";
        return false;
    }
    return true;
}

/// What is drawn: overlays, heatmap, screenshots, window, selection, zoom, fonts, scene view
bool readShow(const Flags& f, GuiOptions& out, QString& message) {
    if (!f.overlays.empty()) {
        const auto o = Overlays::parse(q(f.overlays));
        if (!o) {
            message = "--overlays takes a comma-separated list of cylinder, cone, frontier, misses, samples, grid, all, none";
            return false;
        }
        out.overlays = *o;
    }
    if (!f.heatmap.empty()) {
        const auto h = parseHeatmap(q(f.heatmap));
        if (!h) {
            message = "--heatmap must be none, tests, hitmiss, hitrate, order or beam";
            return false;
        }
        out.heatmap = *h;
    }
    out.screenshot = q(f.screenshot);
    out.record = q(f.record);
    out.every = f.every;
    if (!f.window.empty()) {
        int w = 0, h = 0;
        if (!parsePair(q(f.window).toLower(), 'x', w, h) || w < 200 || h < 200) {
            message = "--window must be WxH, at least 200x200";
            return false;
        }
        out.window = QSize(w, h);
    }
    if (!f.select.empty() && !readSelect(q(f.select), out, message)) return false;
    out.zoom = f.zoom;
    out.largeFonts = f.large;
    out.present = f.present;
    return readSceneView(f, out, message);
}

/// --panels LIST: names of panelNames(), all or none
bool readPanels(const QString& v, GuiOptions& out, QString& message) {
    const QString list = v.trimmed().toLower();
    QStringList shown;
    if (list == "all") shown = panelNames();
    else if (list != "none")
        for (const QString& name : list.split(',')) {
            if (!panelNames().contains(name.trimmed())) {
                message = "--panels takes a comma-separated list of " + panelNames().join(", ") + ", or all or none, not '" + name + "'";
                return false;
            }
            shown << name.trimmed();
        }
    out.panels = shown;
    return true;
}

/// --focus x0,y0,x1,y1 inside the largest image
bool readFocus(const QString& v, GuiOptions& out, QString& message) {
    const QStringList c = v.split(',');
    int r[4] = {0, 0, 0, 0};
    bool ok = c.size() == 4;
    for (int i = 0; ok && i < 4; ++i) ok = parseInt(c[i].trimmed(), 0, kMaxSize, r[i]);
    if (!ok || r[2] <= r[0] || r[3] <= r[1]) {
        message = "--focus must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not '" + v + "'";
        return false;
    }
    out.focus = QRect(QPoint(r[0], r[1]), QPoint(r[2] - 1, r[3] - 1));
    return true;
}

/// Lectures: the tour and its stop, the frame log, the goal to run to, the panels, the focus
bool readLecture(const Flags& f, bool noArguments, GuiOptions& out, QString& message) {
    out.tour = q(f.tour);
    if (f.stop > 0) {
        if (f.tour.empty()) {
            message = "--stop needs --tour";
            return false;
        }
        out.stop = f.stop;
    }
    out.frameLog = q(f.frameLog);
    out.walk = f.walk;
    out.renderAhead = !f.noAhead;
    if (!f.run.empty()) {
        const QString v = q(f.run).trimmed().toLower();
        if (v == "next-miss") out.runTo = rc::RunGoal::NextMiss;
        else if (v == "next-deferral") out.runTo = rc::RunGoal::NextDeferral;
        else {
            message = "--run must be next-miss or next-deferral, not '" + q(f.run) + "'";
            return false;
        }
    }
    if (!f.panels.empty() && !readPanels(q(f.panels), out, message)) return false;
    if (!f.focus.empty() && !readFocus(q(f.focus), out, message)) return false;
    if (!f.missReason.empty()) {
        const QStringList names = missReasonNames();
        const int i = int(names.indexOf(q(f.missReason).trimmed().toLower()));
        if (i < 0) {
            message = "--miss-reason must be " + oneOf(names) + ", not '" + q(f.missReason) + "'";
            return false;
        }
        out.missReason = rc::MissReason(i + 1);
    }
    // No arguments: the first impression
    if (noArguments) {
        out.firstImpression = true;
        out.steps = kFirstImpressionSteps;
        out.overlays = *Overlays::parse("cylinder,cone,frontier");
    }
    return true;
}

}  // namespace

ParseResult parseGuiOptions(const QStringList& args, GuiOptions& out, QString& message) {
    // Declare the options, in the groups the help lists
    CLI::App app("RayCache: step through ray tracing ray by ray, with Hanrahan's (1986) blocker lists,\n"
                 "Speer-DeRose-Barsky cylinders of safety and the breadth-first frontier drawn on the image.\n"
                 "With no display (and no QT_QPA_PLATFORM), renders headless to a PNG and exits.",
                 "raycache-gui");
    Flags f;
    declareRender(app, f);
    declareShow(app, f);
    declareLecture(app, f);
    // --scene-view may come alone (the side view): give it its default value. CLI11 reads
    // its arguments last first.
    std::vector<std::string> argv;
    for (int i = 1; i < args.size(); ++i) {
        const bool alone = args[i] == "--scene-view" && (i + 1 == args.size() || !parseSceneAngle(args[i + 1]));
        argv.push_back(alone ? "--scene-view=side" : args[i].toStdString());
    }
    std::reverse(argv.begin(), argv.end());
    try {
        app.parse(argv);
    } catch (const CLI::CallForHelp&) {
        message = QString::fromStdString(app.help());
        return ParseResult::Help;
    } catch (const CLI::ParseError& e) {
        message = QString::fromStdString(e.what());
        return ParseResult::Error;
    }
    if (!readRender(f, out, message) || !readShow(f, out, message) || !readLecture(f, args.size() <= 1, out, message))
        return ParseResult::Error;
    return ParseResult::Ok;
}

rc::RenderOptions renderOptionsOf(const GuiOptions& o) {
    rc::RenderOptions r;
    r.cache = o.cache;
    r.order = o.order;
    r.accel = o.accel;
    r.band = o.band;
    r.shading.sampling = o.sampling;
    r.width = std::max(0, o.width);
    r.height = std::max(0, o.height);
    return r;
}

rc::RenderOptions sizedOptions(rc::RenderOptions o, int longerSide, const rc::Scene* scene) {
    if (longerSide >= 0 && scene) {
        o.width = o.height = 0;
        if (longerSide > 0) {
            const int w = scene->camera.width, h = scene->camera.height;
            const double longer = std::max(w, h);
            o.width = std::max(1, int(std::lround(longerSide * w / longer)));
            o.height = std::max(1, int(std::lround(longerSide * h / longer)));
        }
    }
    return o;
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
    o.renderAhead = base.renderAhead;
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
