#pragma once
/// \file
/// \brief The command line of raycache-gui.
#include <optional>

#include <QPoint>
#include <QRect>
#include <QSize>
#include <QString>
#include <QStringList>

#include "overlay_options.h"
#include "render/render_session.h"
#include "view/session_state.h"
#include "view/tour.h"
#include "view/viewer_settings.h"

namespace rcgui {

/// A second render to run beside the first: another cache and order, same scene and size.
struct CompareChoice {
    rc::CacheKind cache = rc::CacheKind::None;
    rc::OrderKind order = rc::OrderKind::Scanline;
    bool operator==(const CompareChoice&) const = default;
};
/// Parses "CACHE:ORDER" (e.g. none:scanline, cylinder:bfs); on an error, says why.
std::optional<CompareChoice> parseCompare(const QString& spec, QString& error);
/// "cache:order", as parseCompare() reads it.
QString toString(const CompareChoice& c);

/// How the scene view looks at the scene.
enum class SceneAngle {
    Side,   ///< across the ray in focus, its hull's axis level (the paper's Figure 2)
    Along,  ///< down the ray in focus (the paper's Figure 1)
    Top,    ///< from above (the camera's up)
    Front,  ///< from the eye's side, without perspective
};
QString toString(SceneAngle a);

/// The docks --panels names, in the window's order.
const QStringList& panelNames();
std::optional<SceneAngle> parseSceneAngle(const QString& s);

/// What the command line asks for.
struct GuiOptions {
    QString scene = "cube:4";
    rc::CacheKind cache = rc::CacheKind::Blocker;
    rc::OrderKind order = rc::OrderKind::BreadthFirst;
    int width = 0, height = 0;   ///< image size; 0: the scene's
    qint64 steps = -1;           ///< rays to trace first (-1: none, or 20000 for screenshots)
    Overlays overlays;
    Heatmap heatmap = Heatmap::None;
    QString screenshot;          ///< PNG to write, then exit
    QString record;              ///< folder to write a numbered PNG sequence of the fill to, then exit
    qint64 every = 10000;        ///< steps between recorded frames
    QSize window{1600, 1000};    ///< window size of screenshots
    QPoint select{-1, -1};       ///< pixel to inspect
    QString selectPath;          ///< its ray at this path (cache-tree label, e.g. eye/reflection); empty: the eye ray
    rc::AccelKind accel = rc::AccelKind::Linear;
    int band = rc::kAutoBand;    ///< scanlines per band of breadth-first and progressive orders (0: all)
    rc::Sampling sampling;       ///< distributed ray tracing (--spp, --light-radius, ...), as raycache render takes it
    double zoom = 1.0;           ///< screenshots: zoom relative to "fit", about the ray being traced
    bool largeFonts = false;
    bool present = false;        ///< presentation mode: panels hidden, large fonts
    std::optional<CompareChoice> compare;  ///< --compare CACHE:ORDER: a second render in lockstep
    bool sceneView = false;                ///< --scene-view: show the scene from the side
    SceneAngle sceneAngle = SceneAngle::Side;
    double orbitYaw = 0.0, orbitPitch = 0.0;  ///< --orbit: degrees turned from that angle
    bool sceneGiven = false;
    QRect focus;                 ///< --focus: the image rectangle (pixels) the view fits; empty: the whole image
    rc::MissReason missReason = rc::MissReason::None;  ///< --miss-reason: Next miss stops at this reason only
    QString tour;                ///< --tour: the tour file to open
    int stop = 1;                ///< --stop: its stop to open on (from 1)
    QString frameLog;            ///< --frame-log: one line per UI-thread task, NAME MILLISECONDS
    /// --panels: the docks to show (ray-tree, cache-tree, statistics, event-log, objects);
    /// unset: as they are. A tour's stop shows only those it names.
    std::optional<QStringList> panels;
    /// --run next-miss|next-deferral: after the steps, trace on to the next such ray and focus on it
    std::optional<rc::RunGoal> runTo;
    bool walk = false;           ///< --walk: quit when shown (with --tour: after every stop in turn)
    bool renderAhead = true;     ///< a tour's next stop rendered while this one is shown (--no-render-ahead: not)
    /// No arguments at all: open on a partly traced image with a hit ray in focus, its
    /// hull, blockers and the frontier shown (the paper at a glance).
    bool firstImpression = false;
};

/// The render `o` asks for: cache, order, search, band, samples and size (0 x 0: the scene's).
rc::RenderOptions renderOptionsOf(const GuiOptions& o);

/// `o` at the size the Size box chose: `longerSide` (the scene's aspect kept), the scene's
/// own (0), or `o`'s (< 0).
rc::RenderOptions sizedOptions(rc::RenderOptions o, int longerSide, const rc::Scene* scene);

/// The outcome of parsing.
enum class ParseResult { Ok, Help, Error };

/// Parses `args` (argv, program name first): the viewer's settings (rc::SettingsFlags, with
/// the CLI's limits), then the window's own flags. On Help, `message` is the help text; on
/// Error, it says what is wrong.
ParseResult parseGuiOptions(const QStringList& args, GuiOptions& out, QString& message);

/// `s` in the window's terms, on top of what `out` holds: the settings a stop and the
/// command line share, read by their one reader (rc::SettingsFlags).
void applySettings(const rc::ViewerSettings& s, GuiOptions& out);

/// The options a tour stop stands for: its settings read by rc::stopSettings() (as the
/// page reads them), on top of `base`'s window, fonts and output choices. On an error, `message` is
/// `file:line:column: stop K: ...` and nothing is returned.
std::optional<GuiOptions> stopOptions(const rc::Tour& tour, int stop, const GuiOptions& base, QString& message);

}  // namespace rcgui
