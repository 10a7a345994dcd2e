#pragma once
/// \file
/// \brief A tour stop's claims: comparisons of quantities read from what the stop draws,
/// checked against the render (the same model the Qt window and the web page draw), and
/// the caption's mentions of paths, panes and counts checked against the stop.
///
/// A claim is `A op B`: `op` one of `<`, `<=`, `==`, `!=`, `>=`, `>`; each side a
/// quantity, optionally scaled (`0.5*right.misses`), a number, or a name (`flushed`).
/// A quantity is `[left.|right.]name`: `left` (the default) is the stop's render, `right`
/// its compared one. See claimQuantities() for the names.
#include <optional>
#include <string>
#include <vector>

#include "view/ray_focus.h"
#include "view/session_state.h"
#include "view/tour.h"

namespace rc {

/// What one pane of a stop draws: its render and the selection the overlays follow.
struct ClaimPane {
    const SessionState* state = nullptr;
    Selection selection;
};

/// What a stop shows, as claims read it: its panes (left, then right when it compares),
/// and the overlays, heatmap and panels it names (its settings' values).
struct ClaimView {
    std::vector<ClaimPane> panes;
    std::vector<std::string> overlays;  ///< e.g. misses, cone, cylinder
    std::string heatmap;                ///< "" or none: no heatmap
    std::vector<std::string> panels;    ///< e.g. ray-tree, cache-tree, statistics
};

/// One quantity a claim may name.
struct ClaimQuantity {
    const char* name;
    const char* meaning;
    /// What the stop must show for the quantity to be on screen: an overlay (`misses`), a
    /// panel (`panel:statistics`), a heatmap (`heatmap:tests`), or "" (the caption under
    /// each picture, which is always drawn).
    const char* drawnBy;
    /// Also on screen in a compared stop: the compare caption (rc::compareCaption) gives
    /// it for both panes.
    bool compareCaption = false;
};
/// Every quantity a claim may name, with what it reads and what draws it.
const std::vector<ClaimQuantity>& claimQuantities();

/// A claim parsed: its two sides and operator.
struct Claim {
    struct Side {
        double factor = 1.0;
        std::string pane;      ///< left or right ("" for a literal)
        std::string quantity;  ///< "" for a literal
        std::optional<double> number;
        std::string word;      ///< a literal name, e.g. flushed
    };
    Side lhs, rhs;
    std::string op;
    std::string text;
};

/// Parses `text`; on a malformed claim or an unknown quantity, nothing and `error` says why.
std::optional<Claim> parseClaim(const std::string& text, std::string& error);
/// Why `claim` names something the stop does not draw ("" when it draws it all): a right
/// pane without `compared`, or a quantity whose overlay, heatmap or panel it does not show.
std::string claimNotDrawn(const Claim& claim, bool compared, const std::vector<std::string>& overlays,
                          const std::string& heatmap, const std::vector<std::string>& panels);

/// The overlays, heatmap and panels `stop` names, without panes (the caller adds them).
ClaimView claimViewOf(const TourStop& stop);
/// The stop's claims parsed and checked against what it draws: the first error as a
/// message (empty when all are fine); `out` receives the parsed claims.
std::string parseStopClaims(const TourStop& stop, std::vector<Claim>& out);

/// A quantity's value in a pane: a number, or a name (a path, a miss reason).
struct ClaimValue {
    std::optional<double> number;
    std::string word;
    std::string shown() const;
};
/// The value of quantity `name` in `pane` (nothing, with `error`, when it cannot be read,
/// e.g. no ray in focus).
std::optional<ClaimValue> readQuantity(const ClaimPane& pane, const std::string& name, std::string& error);

/// The result of checking a claim on a render.
struct ClaimResult {
    bool holds = false;
    std::string text;     ///< the claim
    std::string reading;  ///< what was read, e.g. "right.misses = 4324 < left.misses = 7638"
};
ClaimResult checkClaim(const Claim& claim, const ClaimView& view);

/// What a stop's caption says that the stop does not draw: a ray path not in focus in
/// any pane (nor listed by a ray-tree or cache-tree panel), a left or right pane when it
/// does not compare, or a count (digits or a number word from two to twelve, outside
/// quotation marks, figure and table numbers and scene names; decimals are ratios or
/// times, not counts) that none of its claims states.
std::vector<std::string> captionSlips(const std::string& caption, const std::vector<Claim>& claims,
                                      const ClaimView& view);

/// The ray-tree path label (CacheTree::label) of the ray in focus in `pane`, "" for none.
std::string focusPath(const ClaimPane& pane);

}  // namespace rc
