#include "view/legend.h"

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <string_view>

#include "view/overlay_layers.h"
#include "view/ray_focus.h"

namespace rc {

namespace {

/// Concatenates by appending: GCC 12 warns falsely (-Wrestrict, PR105651) about chains of
/// `"literal" + std::string`.
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string s;
    (s.append(std::string_view(parts)), ...);
    return s;
}

bool anyOf(const std::vector<OverlayShape>& drawn, std::initializer_list<ShapeRole> roles) {
    return std::any_of(drawn.begin(), drawn.end(), [&](const OverlayShape& s) {
        return std::find(roles.begin(), roles.end(), s.role) != roles.end();
    });
}

/// 12345 as "12,345", as the page's toLocaleString('en') and Qt's %L write it
std::string grouped(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string pixelText(int pixel, int width) {
    return cat("(", std::to_string(pixel % width), ",", std::to_string(pixel / width), ")");
}

}  // namespace

std::vector<LegendEntry> legendEntries(const SessionState& s, const Selection& sel, const LegendShown& shown,
                                       const std::vector<OverlayShape>& drawn) {
    using namespace colours;
    std::vector<LegendEntry> keys;
    const RenderSession& session = s.session();
    const auto focus = RayFocus::of(s, sel);
    // The ray in focus and its overlays: an entry for each kind of shape drawn
    if ((shown.cylinder || shown.hull) && anyOf(drawn, {ShapeRole::Ray}))
        keys.push_back({kRay, focus && focus->selected ? "selected ray" : "ray being traced"});
    if (shown.cylinder && anyOf(drawn, {ShapeRole::Cylinder, ShapeRole::CachedCylinder, ShapeRole::CylinderAxis}))
        keys.push_back({kCylinder, "cylinder of safety (dashed: around this ray, not cached)"});
    if (shown.hull) {
        if (session.strategy().blockerLists()) {
            if (anyOf(drawn, {ShapeRole::Hull, ShapeRole::EmptyCone, ShapeRole::EmptyConeAxis}))
                keys.push_back({kHull, "blocker hull of origin and target (dashed: empty cone of eye rays)"});
            if (anyOf(drawn, {ShapeRole::Target, ShapeRole::TargetPoint}))
                keys.push_back({kTarget, focus && focus->kind == RayKind::Shadow ? "target (the light)"
                                                                                  : "target (cached object)"});
            if (anyOf(drawn, {ShapeRole::Blocker, ShapeRole::BlockerHit})) {
                // A long list is drawn in part: say how much
                const FocusHull h = focus ? hullOf(s, *focus) : FocusHull{};
                keys.push_back({kBlocker, h.listed > h.blockers.size()
                                              ? cat("potential blockers: the ", std::to_string(h.blockers.size()),
                                                    " nearest of ", grouped(h.listed), " listed")
                                              : std::string("potential blockers")});
            }
        } else {
            keys.push_back({std::nullopt, "blocker hull: blocker cache only"});
        }
    }
    // The breadth-first frontier
    if (shown.frontier) {
        const FrontierView f = session.order().frontier();
        if (f.path >= 0) {
            keys.push_back({kQueued, cat("queued (", std::to_string(f.queued.size()), ")")});
            keys.push_back({kDeferred, cat("deferred seeds (", std::to_string(f.deferred.size()), ")")});
            keys.push_back({kRegion, cat("region ", std::to_string(f.region), " being filled, path ",
                                         session.cacheTree().label(f.path))});
            keys.push_back({kRegionEdge, "edges of finished regions"});
        } else {
            keys.push_back({std::nullopt, "frontier: breadth-first order only"});
        }
    }
    // Miss marks, by reason: counted over every path, marked at the path in focus
    if (shown.misses) {
        const Counters& n = session.counters();
        keys.push_back({std::nullopt, cat("misses marked at path ", session.cacheTree().label(focus ? focus->node : 0),
                                          "; all paths:")});
        for (int r = 1; r < kMissReasons; ++r)
            if (n.missReasons[r] > 0)
                keys.push_back({missReasonColour(MissReason(r)), cat("miss: ", toString(MissReason(r)), " (",
                                                                     std::to_string(n.missReasons[r]), ")")});
    }
    return keys;
}

std::vector<LegendEntry> focusEntries(const SessionState& s, const Selection& sel, const LegendShown& shown,
                                      const std::vector<OverlayShape>& drawn) {
    std::vector<LegendEntry> keys;
    // A miss in focus: what caused it, in words, and in red when its shapes are drawn
    const auto focus = RayFocus::of(s, sel);
    if (focus && (shown.hull || shown.cylinder)) {
        const std::string cause = missCauseText(s, *focus);
        const bool marked = anyOf(drawn, {ShapeRole::CylinderLeft, ShapeRole::MissedTarget, ShapeRole::BlockerHit});
        if (!cause.empty()) keys.push_back({marked ? std::optional<Rgb>(colours::kMissCause) : std::nullopt, cause});
    }
    if (sel.pixel >= 0) keys.push_back({colours::kSelection, cat("selected pixel ", pixelText(sel.pixel, s.width()))});
    return keys;
}

}  // namespace rc
