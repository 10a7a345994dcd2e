#include "gui_options.h"

#include <cmath>

#include <algorithm>

#include <CLI/CLI.hpp>

#include "labels.h"
#include "order/order_registry.h"
#include "view/viewer_settings.h"

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
QString q(const std::string& s) { return QString::fromStdString(s); }
}  // namespace

std::optional<CompareChoice> parseCompare(const QString& spec, QString& error) {
    std::string cache, order, why;
    if (!rc::readCompare(spec.toStdString(), cache, order, why)) {
        error = q(why);
        return std::nullopt;
    }
    return CompareChoice{*rc::parseCacheKind(cache), *rc::parseOrderKind(order)};
}

QString toString(const CompareChoice& c) {
    return QString("%1:%2").arg(QString::fromUtf8(rc::toString(c.cache).data()),
                                QString::fromUtf8(rc::toString(c.order).data()));
}

QString toString(SceneAngle a) {
    // The core's names (rc::sceneAngleNames), in the enum's order
    return q(rc::sceneAngleNames().at(std::size_t(a)));
}

const QStringList& panelNames() {
    static const QStringList names = [] {
        QStringList out;
        for (const std::string& n : rc::panelNames()) out << q(n);
        return out;
    }();
    return names;
}

std::optional<SceneAngle> parseSceneAngle(const QString& s) {
    for (SceneAngle a : {SceneAngle::Side, SceneAngle::Along, SceneAngle::Top, SceneAngle::Front})
        if (s.trimmed().toLower() == toString(a)) return a;
    return std::nullopt;
}

namespace {

/// The window's own flags as CLI11 reads them: what no tour stop sets
struct WindowFlags {
    std::string screenshot, window, record, tour, frameLog;
    int stop = 0;
    qint64 every = 10000;
    bool large = false, present = false, walk = false, noAhead = false;
};

/// Where the window goes: screenshots, sequences, its size, its fonts
void declareWindow(CLI::App& app, WindowFlags& f) {
    app.add_option("--screenshot", f.screenshot, "write the window to this PNG and exit");
    app.add_option("--window", f.window, "window size of screenshots (default 1600x1000)");
    app.add_option("--record", f.record, "write a numbered PNG sequence of the fill (overlays on) to this folder, then exit");
    app.add_option("--every", f.every, "--record: steps between frames (default 10000)")->check(CLI::PositiveNumber);
    app.add_flag("--large-fonts", f.large, "bigger text, for a projector");
    app.add_flag("--present", f.present, "presentation mode: the panels hidden, large fonts (F11 in the window)");
}

/// Lectures: tours, their stops, the frame log
void declareLecture(CLI::App& app, WindowFlags& f) {
    app.add_option("--tour", f.tour, "open a tour: a JSON file of stops, each a caption and what to show (PageDown/PageUp move)");
    app.add_option("--stop", f.stop, "--tour: the stop to open on, from 1 (default 1)")->check(CLI::Range(1, 100000));
    app.add_option("--frame-log", f.frameLog, "write one line per UI-thread task, NAME MILLISECONDS, to this file (with a tour, also stop-K-picture: from a stop asked for to its picture complete)");
    app.add_flag("--walk", f.walk, "quit once shown (with --tour: show every stop from --stop on in turn, then quit): for --frame-log");
    app.add_flag("--no-render-ahead", f.noAhead, "--tour: render each stop only when it is reached, not while the one before is shown");
}

/// The window's own: outputs, its size, fonts, the tour and its stop, the frame log
bool readWindow(const WindowFlags& f, GuiOptions& out, QString& message) {
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
    out.largeFonts = f.large;
    out.present = f.present;
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
    return true;
}

/// What is drawn, in the window's terms: overlays, heatmap, selection, focus, zoom, scene view, panels
void showOf(const rc::ViewerSettings& s, GuiOptions& out) {
    if (s.overlays) {
        Overlays o;
        for (const std::string& name : *s.overlays) o.turnOn(name);
        out.overlays = o;
    }
    out.heatmap = s.heatmap.empty() ? Heatmap::None : *parseHeatmap(q(s.heatmap));
    if (s.select) {
        out.select = QPoint(s.select->x, s.select->y);
        out.selectPath = q(s.select->path);
    }
    if (s.focus) out.focus = QRect(QPoint((*s.focus)[0], (*s.focus)[1]), QPoint((*s.focus)[2] - 1, (*s.focus)[3] - 1));
    out.zoom = s.zoom.value_or(1.0);
    out.sceneView = !s.sceneView.empty();
    if (out.sceneView) out.sceneAngle = *parseSceneAngle(q(s.sceneView));
    out.orbitYaw = s.orbitYaw;
    out.orbitPitch = s.orbitPitch;
    if (s.panels) {
        QStringList shown;
        for (const std::string& p : *s.panels) shown << q(p);
        out.panels = shown;
    }
}

}  // namespace

void applySettings(const rc::ViewerSettings& s, GuiOptions& out) {
    if (!s.scene.empty()) {
        out.scene = q(s.scene);
        out.sceneGiven = true;
    }
    const rc::RenderOptions r = rc::renderOptionsOf(s);
    out.cache = r.cache;
    out.order = r.order;
    out.accel = r.accel;
    out.width = s.width;
    out.height = s.height;
    out.band = s.band;
    out.sampling = s.sampling;
    if (s.steps >= 0) out.steps = s.steps;
    if (!s.compareCache.empty())
        out.compare = CompareChoice{*rc::parseCacheKind(s.compareCache), *rc::parseOrderKind(s.compareOrder)};
    showOf(s, out);
    if (s.run == "next-miss") out.runTo = rc::RunGoal::NextMiss;
    else if (s.run == "next-deferral") out.runTo = rc::RunGoal::NextDeferral;
    for (int i = 1; i < rc::kMissReasons; ++i)
        if (s.missReason == rc::toString(rc::MissReason(i))) out.missReason = rc::MissReason(i);
}

ParseResult parseGuiOptions(const QStringList& args, GuiOptions& out, QString& message) {
    // The viewer's settings, as the tours' stops are read (view/viewer_settings.h), then the window's own
    CLI::App app("RayCache: step through ray tracing ray by ray, with Hanrahan's (1986) blocker lists,\n"
                 "Speer-DeRose-Barsky cylinders of safety and the breadth-first frontier drawn on the image.\n"
                 "With no display (and no QT_QPA_PLATFORM), renders headless to a PNG and exits.",
                 "raycache-gui");
    const rc::SettingsFlags settings(app);
    WindowFlags f;
    declareWindow(app, f);
    declareLecture(app, f);
    std::vector<std::string> given;
    for (int i = 1; i < args.size(); ++i) given.push_back(args[i].toStdString());
    std::vector<std::string> argv = rc::parseOrder(given);
    try {
        app.parse(argv);
    } catch (const CLI::CallForHelp&) {
        message = QString::fromStdString(app.help());
        return ParseResult::Help;
    } catch (const CLI::ParseError& e) {
        message = QString::fromStdString(e.what());
        return ParseResult::Error;
    }
    // A tour's stops set the viewer's settings: one given beside --tour would be dropped unseen
    if (!f.tour.empty())
        for (const std::string& name : rc::settingNames())
            if (app.count(name == "scene" ? name : "--" + name) > 0) {
                message = q("--tour: each stop sets its own " + name + "; give it in the tour file, not beside --tour");
                return ParseResult::Error;
            }
    rc::ViewerSettings s;
    std::string why;
    if (!settings.read(s, why)) {
        message = q(why);
        return ParseResult::Error;
    }
    applySettings(s, out);
    if (!readWindow(f, out, message)) return ParseResult::Error;
    // No arguments: the first impression
    if (args.size() <= 1) {
        out.firstImpression = true;
        out.steps = kFirstImpressionSteps;
        out.overlays = *Overlays::parse("cylinder,cone,frontier");
    }
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
    // The one reader of a stop, the page's too (rc::stopSettings)
    GuiOptions o;
    try {
        applySettings(rc::stopSettings(tour, stop), o);
    } catch (const rc::TourError& e) {
        message = QString::fromStdString(e.what());
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
