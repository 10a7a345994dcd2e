#pragma once
/// \file
/// \brief Turns per-pixel tallies of a render into a false-colour picture.
#include <optional>

#include <QImage>

#include "overlay_options.h"
#include "view/session_state.h"

namespace rcgui {

/// Builds heatmap pictures; untraced pixels are black.
class HeatmapBuilder {
public:
    /// The picture of `mode` (Heatmap::None gives the rendered image). `path` is the
    /// ray-tree path of the beam-tree heatmap.
    /// `top` fixes the value that maps to the top of the colour ramp (tests per pixel, or
    /// steps for the visiting order); 0 takes the state's own largest value. Two renders
    /// compared side by side share one `top`, so equal colours mean equal values.
    static QImage build(const rc::SessionState& s, Heatmap mode, int path = 0, double top = 0.0);
    /// The state's own top of the scale for `mode`: its most tests in one pixel, or its
    /// step count (at least 1), or 1 for the hit rate; 0 for pictures without a scale.
    static double scaleOf(const rc::SessionState& s, Heatmap mode);
    /// The cache hit rate of pixel `px`: hits / (hits + misses) over the lookups of every
    /// ray of the pixel, all samples; nothing when it made none (no cache, or untraced).
    static std::optional<double> hitRate(const rc::SessionState& s, int px);
};

}  // namespace rcgui
