#pragma once
/// \file
/// \brief Turns per-pixel tallies of a render into a false-colour picture.
#include <QImage>

#include "overlay_options.h"
#include "session_state.h"

namespace rcgui {

/// Builds heatmap pictures; untraced pixels are black.
class HeatmapBuilder {
public:
    /// The picture of `mode` (Heatmap::None gives the rendered image). `path` is the
    /// ray-tree path of the beam-tree heatmap.
    static QImage build(const SessionState& s, Heatmap mode, int path = 0);
};

}  // namespace rcgui
