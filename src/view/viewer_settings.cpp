#include "view/viewer_settings.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "search/counters.h"
#include "trace/shading.h"
#include "view/flag_definitions.h"
#include "view/overlay_registry.h"

namespace rc {

const std::vector<std::string>& heatmapNames() {
    static const std::vector<std::string> names{"none", "tests", "hitmiss", "hitrate", "order", "beam"};
    return names;
}

const std::vector<std::string>& sceneAngleNames() {
    static const std::vector<std::string> names{"side", "along", "top", "front"};
    return names;
}

const std::vector<std::string>& panelNames() {
    static const std::vector<std::string> names{"ray-tree", "cache-tree", "statistics", "event-log", "objects"};
    return names;
}

namespace {

/// The largest pixel coordinate, the CLI's largest image
constexpr int kMaxSize = int(NffLimits::maxResolution);

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
    return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

/// `text` split at `sep`, each part trimmed (empty parts kept)
std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string w; std::getline(in, w, sep);) out.push_back(trimmed(w));
    if (!text.empty() && text.back() == sep) out.push_back("");
    return out;
}

/// A whole number in [lo, hi], the whole of `s`
bool wholeNumber(const std::string& s, int lo, int hi, int& out) {
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) return false;
    out = v;
    return true;
}

/// A finite number, the whole of `s`
bool finite(const std::string& s, double& out) {
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size() && std::isfinite(out);
}

/// "a, b or c"
std::string oneOf(std::vector<std::string> names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return out;
}

bool among(const std::vector<std::string>& names, const std::string& s) {
    return std::find(names.begin(), names.end(), s) != names.end();
}

/// The miss reasons' names, from Cold on
std::vector<std::string> missReasonNames() {
    std::vector<std::string> out;
    for (int i = 1; i < kMissReasons; ++i) out.emplace_back(toString(MissReason(i)));
    return out;
}

}  // namespace

/// The options' values as CLI11 reads them, before they are checked and become settings
struct SettingsFlags::Values {
    std::vector<std::string> scenes;
    std::string cache, order, accel, compare, overlays, heatmap, select, sceneView, orbit, focus, missReason, panels, run;
    int width = 0, height = 0, band = kAutoBand;
    std::int64_t steps = -1;
    double zoom = 1.0;
    CLI::Option* zoomGiven = nullptr;
    Sampling sampling;
};

bool readCompare(const std::string& spec, std::string& cache, std::string& order, std::string& error) {
    const std::vector<std::string> parts = split(lower(trimmed(spec)), ':');
    if (parts.size() != 2 || !parseCacheKind(parts[0]) || !parseOrderKind(parts[1])) {
        error = "--compare must be CACHE:ORDER, with CACHE " + oneOf(cacheRegistry().names()) + " and ORDER " +
                oneOf(orderRegistry().names()) + " (e.g. none:scanline), not '" + spec + "'";
        return false;
    }
    cache = parts[0];
    order = parts[1];
    return true;
}

SettingsFlags::SettingsFlags(CLI::App& app) : v_(std::make_unique<Values>()) {
    Values& f = *v_;
    // What renders: the options the CLI has too (view/flag_definitions.h)
    app.add_option("scene", f.scenes, "an .nff file or a built-in such as cube:4 (default cube:4)");
    cli::addCacheOption(&app, f.cache);
    cli::addOrderOption(&app, f.order);
    cli::addAccelOption(&app, f.accel, true);
    cli::addSizeOptions(&app, f.width, f.height);
    cli::addBandOption(&app, f.band);
    cli::addSamplingOptions(&app, f.sampling, true);
    app.add_option("--seed", f.sampling.seed, "seed of distributed ray tracing's samples (default 1986)");
    app.add_option("--steps", f.steps, "rays to trace before showing (screenshots: default 20000)")->check(CLI::NonNegativeNumber);
    app.add_option("--compare", f.compare, "run a second render (another cache and order) in lockstep beside the first, e.g. none:scanline");
    // What is drawn, and how the view looks at it
    app.add_option("--overlays", f.overlays, "cylinder,cone,frontier,misses,samples (or all, none, grid)");
    app.add_option("--heatmap", f.heatmap, oneOf(heatmapNames()));
    app.add_option("--select", f.select, "pixel to inspect, and which of its rays (a path such as eye/reflection/shadow 1; default its eye ray): x,y[:path]");
    f.zoomGiven = app.add_option("--zoom", f.zoom, "zoom factor (relative to fitting the window) about the ray being traced, or the selected pixel")
                      ->check(cli::finiteNumber())->check(CLI::Range(0.1, 200.0));
    app.add_option("--scene-view", f.sceneView, "show the 3D scene beside the image: side (across the ray in focus, the paper's Figure 2), along (down the ray, Figure 1), top or front");
    app.add_option("--orbit", f.orbit, "--scene-view: turn the view by YAW,PITCH degrees");
    app.add_option("--focus", f.focus, "fit the view to this image rectangle, in pixels: x0,y0,x1,y1");
    app.add_option("--panels", f.panels, "the panels to show: " + oneOf(panelNames()) + ", all or none");
    // Where the rays run to
    app.add_option("--miss-reason", f.missReason, "Next miss stops only at misses of this reason (" + oneOf(missReasonNames()) + ")");
    app.add_option("--run", f.run, "after --steps, trace on to the next-miss (of --miss-reason, if given) or next-deferral, and focus on it");
}

SettingsFlags::~SettingsFlags() = default;

namespace {

/// The render's choices: the names the shared options checked, and what no one flag can check
bool readRender(const auto& f, ViewerSettings& out, std::string& error) {
    if (f.scenes.size() > 1) {
        error = "only one scene may be given";
        return false;
    }
    if (!f.scenes.empty()) out.scene = f.scenes[0];
    if (!f.cache.empty()) out.cache = f.cache;
    if (!f.order.empty()) out.order = f.order;
    if (!f.accel.empty()) out.accel = f.accel;
    out.width = f.width;
    out.height = f.height;
    out.band = f.band;
    out.steps = f.steps;
    out.sampling = f.sampling;
    if (!f.compare.empty() && !readCompare(f.compare, out.compareCache, out.compareOrder, error)) return false;
    // The core's own check, so the limits are the CLI's
    if (const auto e = samplingError(out.sampling, ShadingOptions{}.maxDepth)) {
        error = *e;
        return false;
    }
    return true;
}

/// --overlays: registered names and aliases, all or none
bool readOverlays(const std::string& v, ViewerSettings& out, std::string& error) {
    std::vector<std::string> names;
    auto add = [&names](const std::string& n) {
        if (!among(names, n)) names.push_back(n);
    };
    for (const std::string& raw : split(v, ',')) {
        const std::string w = lower(raw);
        if (w.empty()) continue;
        if (w == "all") {
            for (const OverlayInfo& o : overlayRegistry().entries()) add(o.name);
        } else if (w == "none") {
            names.clear();
        } else if (const std::string n = overlayNamed(w); !n.empty()) {
            add(n);
        } else {
            error = "--overlays takes a comma-separated list of " + oneOf(overlayRegistry().names()) +
                    " (or another name of one, such as cone), all or none, not '" + raw + "'";
            return false;
        }
    }
    out.overlays = names;
    return true;
}

/// --select x,y or x,y:path
bool readSelect(const std::string& v, ViewerSettings& out, std::string& error) {
    const auto colon = v.find(':');
    StopSelect s;
    if (colon != std::string::npos) {
        s.path = trimmed(v.substr(colon + 1));
        if (s.path.empty()) {
            error = "--select x,y:path needs a path after ':' (e.g. eye/reflection)";
            return false;
        }
    }
    const std::vector<std::string> xy = split(v.substr(0, colon), ',');
    if (xy.size() != 2 || !wholeNumber(xy[0], 0, kMaxSize - 1, s.x) || !wholeNumber(xy[1], 0, kMaxSize - 1, s.y)) {
        error = "--select must be x,y or x,y:path, not '" + v + "'";
        return false;
    }
    out.select = s;
    return true;
}

/// --focus x0,y0,x1,y1 inside the largest image
bool readFocus(const std::string& v, ViewerSettings& out, std::string& error) {
    const std::vector<std::string> c = split(v, ',');
    std::array<int, 4> r{};
    bool ok = c.size() == 4;
    for (std::size_t i = 0; ok && i < 4; ++i) ok = wholeNumber(c[i], 0, kMaxSize, r[i]);
    if (!ok || r[2] <= r[0] || r[3] <= r[1]) {
        error = "--focus must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not '" + v + "'";
        return false;
    }
    out.focus = r;
    return true;
}

/// --scene-view ANGLE and --orbit YAW,PITCH
bool readSceneView(const std::string& angle, const std::string& orbit, ViewerSettings& out, std::string& error) {
    if (!angle.empty()) {
        out.sceneView = lower(trimmed(angle));
        if (!among(sceneAngleNames(), out.sceneView)) {
            error = "--scene-view must be " + oneOf(sceneAngleNames()) + ", not '" + angle + "'";
            return false;
        }
    }
    if (orbit.empty()) return true;
    const std::vector<std::string> parts = split(orbit, ',');
    const bool ok = parts.size() == 2 && finite(parts[0], out.orbitYaw) && finite(parts[1], out.orbitPitch);
    if (!ok || std::abs(out.orbitYaw) > 360 || std::abs(out.orbitPitch) > 90) {
        error = "--orbit must be YAW,PITCH in degrees (|yaw| <= 360, |pitch| <= 90), not '" + orbit + "'";
        return false;
    }
    return true;
}

/// --panels LIST: names of panelNames(), all or none
bool readPanels(const std::string& v, ViewerSettings& out, std::string& error) {
    const std::string list = lower(trimmed(v));
    std::vector<std::string> shown;
    if (list == "all") shown = panelNames();
    else if (list != "none")
        for (const std::string& name : split(list, ',')) {
            if (!among(panelNames(), name)) {
                error = "--panels takes a comma-separated list of " + oneOf(panelNames()) + ", or all or none, not '" + name + "'";
                return false;
            }
            shown.push_back(name);
        }
    out.panels = shown;
    return true;
}

/// What is drawn: overlays, heatmap, selection, focus, zoom, scene view, panels
bool readShow(const auto& f, ViewerSettings& out, std::string& error) {
    if (!f.overlays.empty() && !readOverlays(f.overlays, out, error)) return false;
    if (!f.heatmap.empty()) {
        const std::string h = lower(trimmed(f.heatmap));
        if (!among(heatmapNames(), h)) {
            error = "--heatmap must be " + oneOf(heatmapNames()) + ", not '" + f.heatmap + "'";
            return false;
        }
        out.heatmap = h == "none" ? "" : h;
    }
    if (!f.select.empty() && !readSelect(f.select, out, error)) return false;
    if (!f.focus.empty() && !readFocus(f.focus, out, error)) return false;
    if (f.zoomGiven->count() > 0) out.zoom = f.zoom;
    if (!f.panels.empty() && !readPanels(f.panels, out, error)) return false;
    return readSceneView(f.sceneView, f.orbit, out, error);
}

/// Where the rays run to: --run and --miss-reason
bool readRun(const auto& f, ViewerSettings& out, std::string& error) {
    if (!f.run.empty()) {
        out.run = lower(trimmed(f.run));
        if (out.run != "next-miss" && out.run != "next-deferral") {
            error = "--run must be next-miss or next-deferral, not '" + f.run + "'";
            return false;
        }
    }
    if (!f.missReason.empty()) {
        out.missReason = lower(trimmed(f.missReason));
        if (!among(missReasonNames(), out.missReason)) {
            error = "--miss-reason must be " + oneOf(missReasonNames()) + ", not '" + f.missReason + "'";
            return false;
        }
    }
    return true;
}

}  // namespace

bool SettingsFlags::read(ViewerSettings& out, std::string& error) const {
    return readRender(*v_, out, error) && readShow(*v_, out, error) && readRun(*v_, out, error);
}

const std::vector<std::string>& settingNames() {
    static const std::vector<std::string> names = [] {
        CLI::App app;
        app.set_help_flag();  // no --help: only the settings
        const SettingsFlags flags(app);
        std::vector<std::string> out;
        for (const CLI::Option* o : app.get_options()) {
            std::string n = o->get_name();
            out.push_back(n.rfind("--", 0) == 0 ? n.substr(2) : n);
        }
        return out;
    }();
    return names;
}

std::vector<std::string> parseOrder(const std::vector<std::string>& args) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool alone = args[i] == "--scene-view" && (i + 1 == args.size() || !among(sceneAngleNames(), lower(args[i + 1])));
        out.push_back(alone ? "--scene-view=side" : args[i]);
    }
    std::reverse(out.begin(), out.end());
    return out;
}

std::string readSettings(const std::vector<std::string>& args, ViewerSettings& out) {
    CLI::App app("the viewer's settings");
    const SettingsFlags flags(app);
    std::vector<std::string> argv = parseOrder(args);
    try {
        app.parse(argv);
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
    std::string error;
    return flags.read(out, error) ? "" : error;
}

namespace {
/// A stop's settings as flags, but its scene: `scene` (nothing when empty)
std::vector<std::string> settingArguments(const TourStop& st, const std::string& scene) {
    std::vector<std::string> args;
    for (const TourSetting& s : st.settings) {
        if (s.key == "scene") {
            if (!scene.empty()) args.push_back(scene);
            continue;
        }
        // --key=value: a value that starts with '-' (an orbit of -30,10) is still the key's
        args.push_back("--" + s.key + (s.value.empty() ? "" : "=" + s.value));
    }
    return args;
}
}  // namespace

std::vector<std::string> stopArguments(const Tour& tour, int k) {
    const TourStop& st = tour.stops.at(std::size_t(k - 1));
    // A relative scene path: beside the tour
    return settingArguments(st, st.value("scene").empty() ? "" : stopScene(tour, st));
}

ViewerSettings shownSettings(const TourStop& st) {
    ViewerSettings s;
    if (!readSettings(settingArguments(st, ""), s).empty()) return {};
    return s;
}

ViewerSettings stopSettings(const Tour& tour, int k) {
    if (k < 1 || k > int(tour.stops.size()))
        throw TourError(tour.file, 0, 0, "no stop " + std::to_string(k) + " (it has " + std::to_string(tour.stops.size()) + ")");
    const TourStop& st = tour.stops[std::size_t(k - 1)];
    ViewerSettings s;
    if (const std::string why = readSettings(stopArguments(tour, k), s); !why.empty())
        throw TourError(tour.file, st.line, st.column, "stop " + std::to_string(k) + " (" + st.title + "): " + why);
    return s;
}

RenderOptions renderOptionsOf(const ViewerSettings& s) {
    RenderOptions r;
    r.cache = *parseCacheKind(s.cache);
    r.order = *parseOrderKind(s.order);
    r.accel = *parseAccelKind(s.accel);
    r.band = s.band;
    r.shading.sampling = s.sampling;
    r.width = std::max(0, s.width);
    r.height = std::max(0, s.height);
    return r;
}

}  // namespace rc
