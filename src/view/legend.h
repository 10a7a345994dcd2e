#pragma once
/// \file
/// \brief The key beside the picture: one entry per thing drawn, for both front ends (the Qt
/// GUI's OverlayPainter::paintLegend and the web page, through the bindings' `keys`). An
/// overlay's entry is there only when one of its shapes is drawn. RayCache's own addition.
#include <optional>
#include <string>
#include <vector>

#include "view/overlay_shapes.h"
#include "view/palette.h"
#include "view/session_state.h"

namespace rc {

/// One line of the key: a colour swatch (none for a heading or a note) and its text.
struct LegendEntry {
    std::optional<Rgb> colour;
    std::string text;
    bool operator==(const LegendEntry&) const = default;
};

/// What the view shows, as far as the key is concerned.
struct LegendShown {
    bool cylinder = false;  ///< the cylinder overlay is on
    bool hull = false;      ///< the hull overlay is on
    bool frontier = false;  ///< the breadth-first frontier is on
    bool misses = false;    ///< the miss markers are on
};

/// The key's entries for the overlays `shown` of the render `s` with selection `sel`, when
/// `drawn` are the shapes of the ray in focus the view draws (rc::focusShapes, clipped):
/// the ray, the cylinder, the hull, the target and the blockers each only when a shape of
/// theirs is among them; then the frontier and the misses by reason.
std::vector<LegendEntry> legendEntries(const SessionState& s, const Selection& sel, const LegendShown& shown,
                                       const std::vector<OverlayShape>& drawn);

/// The key's last entries, after any of a front end's own (the GUI's sample rays): the miss
/// in focus's cause in words (in red when its shapes are drawn) and the selected pixel.
std::vector<LegendEntry> focusEntries(const SessionState& s, const Selection& sel, const LegendShown& shown,
                                      const std::vector<OverlayShape>& drawn);

}  // namespace rc
