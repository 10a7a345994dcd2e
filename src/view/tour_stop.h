#pragma once
/// \file
/// \brief A tour stop applied: its settings, read by the one reader of the viewer's settings
/// (view/viewer_settings.h, which the Qt window reads its stops with too), planned as the
/// page sets them (the render's choices, the overlays, the view), and its rays (steps, the
/// run to the miss it shows, its selection) applied to a render. The web page reads stops
/// through this (its bindings); RayCache's own addition, not the paper's.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "view/ray_focus.h"
#include "view/session_state.h"
#include "view/tour.h"
#include "view/viewer_settings.h"

namespace rc {

/// Stop `k` of a tour as the page applies it: its ViewerSettings (stopSettings()) in the
/// page's terms. Empty strings and zeros are settings the stop leaves to the viewer's defaults.
struct StopPlan {
    std::string scene;  ///< resolved against the tour's folder (rc::stopScene)
    int width = 0, height = 0;  ///< 0: the scene's own
    std::string cache = "blocker", order = "bfs", accel = "linear";
    int band = -1;  ///< scanlines per band (rc::RenderOptions::band; -1: chosen by cache and search)
    std::string compareCache, compareOrder;  ///< the compared render's, both "" when none
    std::vector<std::string> overlays;       ///< the overlays' names (rc::overlayNamed), "all" expanded
    std::string heatmap;                     ///< "" for none, e.g. tests
    std::int64_t steps = 0;                  ///< rays traced first
    std::string run;                         ///< "", next-miss or next-deferral (the page runs to a miss only)
    std::string missReason;                  ///< the miss next-miss stops at ("" for any)
    std::optional<StopSelect> select;
    std::optional<std::vector<double>> focus;  ///< the image rectangle shown: x0, y0, x1, y1
    double zoom = 0;                           ///< > 1: the view that much smaller, about the pixel in focus
    /// A scene view with no ray chosen shows a ray worth seeing (rc::showcaseEvent)
    bool showcase = false;
    /// What only the Qt window shows (the scene view, panels, other heatmaps, the sampling
    /// settings), each in words: the page says so rather than dropping it.
    std::vector<std::string> qtOnly;
    bool has(const std::string& overlay) const;
};

/// Reads stop `k` (from 1) of `tour` (stopSettings()). \throws TourError when it has no
/// such stop or a setting is wrong, as the Qt window reports it.
StopPlan planOf(const Tour& tour, int k);

/// What applying a stop's rays gave: the selection to show, and what could not be met.
struct StopApplied {
    Selection selection;
    std::vector<std::string> notes;  ///< e.g. "no such miss before the end"
};

/// Applies the stop's rays to `state` (a render of its settings, freshly opened): its
/// steps, the run to the miss it shows (which comes in focus), the showcase ray, its
/// selection.
StopApplied applyStopRays(SessionState& state, const StopPlan& plan);

}  // namespace rc
