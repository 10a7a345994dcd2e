#pragma once
/// \file
/// \brief What a viewer is set to, read in one place: the settings a tour stop holds and the
/// Qt GUI's command line takes (the scene, its size, cache, order, search, samples, what is
/// compared, the overlays, the pixel in focus, the steps, ...). One set of CLI11 definitions
/// reads them, with the CLI's limits (view/flag_definitions.h). The GUI declares its
/// window's own flags beside them; the Qt window and the web page read a tour stop with
/// stopSettings(). RayCache's own addition, not the paper's.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/render_session.h"
#include "view/tour.h"

namespace CLI {
class App;
}

namespace rc {

/// A `select`: a pixel and, optionally, the ray-tree path of its ray to focus.
struct StopSelect {
    int x = 0, y = 0;
    std::string path;  ///< "" for the pixel's eye ray
};

/// The viewer's settings. Each is checked when read: names are registered ones, numbers lie
/// within the CLI's limits. What is not given keeps the default below.
struct ViewerSettings {
    std::string scene;  ///< "" when not given
    std::string cache = "blocker", order = "bfs", accel = "linear";  ///< registered names
    int width = 0, height = 0;  ///< 0: the scene's own
    int band = kAutoBand;       ///< scanlines per band (RenderOptions::band)
    Sampling sampling;          ///< distributed ray tracing's samples
    std::int64_t steps = -1;    ///< rays traced first (-1: not given)
    std::string compareCache, compareOrder;  ///< the compared render's, both "" when none
    /// The overlays by their registered names (rc::overlayNamed), "all" expanded; unset: not given
    std::optional<std::vector<std::string>> overlays;
    std::string heatmap;  ///< one of heatmapNames() but "none"; "" for none
    std::optional<StopSelect> select;
    std::optional<std::array<int, 4>> focus;  ///< the image rectangle shown: x0, y0, x1, y1 (x0 < x1, y0 < y1)
    std::optional<double> zoom;               ///< the view that much closer about the ray in focus
    std::string sceneView;                    ///< one of sceneAngleNames(), or "" for no scene view
    double orbitYaw = 0.0, orbitPitch = 0.0;  ///< degrees the scene view is turned
    std::string missReason;                   ///< the miss next-miss stops at ("" for any)
    std::string run;                          ///< "", next-miss or next-deferral
    std::optional<std::vector<std::string>> panels;  ///< of panelNames(); unset: not given
};

/// The heatmaps' names: none, tests, hitmiss, hitrate, order, beam.
const std::vector<std::string>& heatmapNames();
/// The scene view's angles: side, along, top, front.
const std::vector<std::string>& sceneAngleNames();
/// The Qt window's panels a setting may name: ray-tree, cache-tree, statistics, event-log, objects.
const std::vector<std::string>& panelNames();

/// A compared render's "CACHE:ORDER" (e.g. none:scanline; any case, spaces around the parts
/// allowed) into its registered names, or false and a sentence in `error` naming the choices.
/// The GUI's compare box and its --compare flag both read it here.
bool readCompare(const std::string& spec, std::string& cache, std::string& order, std::string& error);

/// The viewer's options declared on a CLI11 app (a command line adds its own beside them).
class SettingsFlags {
public:
    explicit SettingsFlags(CLI::App& app);
    ~SettingsFlags();
    SettingsFlags(const SettingsFlags&) = delete;
    SettingsFlags& operator=(const SettingsFlags&) = delete;
    /// After the app has parsed: the settings into `out`, or false and a sentence in `error`.
    bool read(ViewerSettings& out, std::string& error) const;

private:
    struct Values;
    std::unique_ptr<Values> v_;
};

/// The settings' names, without the dashes, as SettingsFlags declares them: "scene", "cache", ...
const std::vector<std::string>& settingNames();

/// `args` (the program's name left out) as CLI::App::parse takes them: last first, and a
/// `--scene-view` with no angle after it given its default, side.
std::vector<std::string> parseOrder(const std::vector<std::string>& args);

/// Reads `args` (the program's name left out) as the viewer's options alone. "" when they
/// are read, else what is wrong, a sentence.
std::string readSettings(const std::vector<std::string>& args, ViewerSettings& out);

/// Stop `k` (from 1) of `tour` as a command line: each setting a flag, the scene (resolved
/// against the tour's folder, rc::stopScene) the one argument.
std::vector<std::string> stopArguments(const Tour& tour, int k);

/// What stop `st` shows (overlays, heatmap, panels, ...), read by readSettings() as
/// stopSettings() reads it, its scene left out: what is drawn does not depend on it. A stop
/// that is not read (the tour's loading reports it) shows nothing set.
ViewerSettings shownSettings(const TourStop& st);

/// Stop `k` (from 1) of `tour`, read by readSettings(). \throws TourError
/// `file:line:column: stop K (title): why` when it is not read, or when there is no stop `k`.
ViewerSettings stopSettings(const Tour& tour, int k);

/// The render the settings ask for: cache, order, search, band, samples and size.
RenderOptions renderOptionsOf(const ViewerSettings& s);

}  // namespace rc
