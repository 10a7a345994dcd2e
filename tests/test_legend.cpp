// The viewer model both front ends draw with: each shape role's style and the key's
// entries (view/palette.h, view/legend.h). The Qt GUI and the page read these, so the key
// names an overlay only when one of its shapes is drawn.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <tuple>

#include "scene/builtin_scenes.h"
#include "view/legend.h"
#include "view/overlay_registry.h"
#include "view/palette.h"
#include "view/ray_focus.h"
#include "view/session_state.h"

namespace {

rc::SessionState session(const char* scene, rc::CacheKind cache, int size) {
    rc::RenderOptions o;
    o.cache = cache;
    o.width = o.height = size;
    return rc::SessionState({std::make_shared<const rc::Scene>(rc::loadScene(scene)), o});
}

bool hasText(const std::vector<rc::LegendEntry>& keys, const std::string& prefix) {
    return std::any_of(keys.begin(), keys.end(), [&](const rc::LegendEntry& e) { return e.text.rfind(prefix, 0) == 0; });
}

}  // namespace

TEST_CASE("Every shape role has a style: a line or a star, in a colour of its own kind", "[view][palette]") {
    std::set<std::string> names;
    for (int r = 0; r < rc::kShapeRoles; ++r) {
        const rc::ShapeRole role = rc::ShapeRole(r);
        const rc::RoleStyle st = rc::roleStyle(role);
        INFO(rc::toString(role));
        names.insert(rc::toString(role));
        CHECK((st.star > 0.0) != (st.width > 0.0));
        if (st.star > 0.0) CHECK((st.arms == 2 || st.arms == 4));
        CHECK(st.fill >= 0);
        CHECK(st.fill <= 255);
        CHECK_FALSE(st.colour == rc::Rgb{});
    }
    CHECK(int(names.size()) == rc::kShapeRoles);
    // The heatmap ramp runs from dark violet to yellow, and every miss reason has its colour
    CHECK(rc::heatRamp(0.0) == rc::Rgb{68, 1, 84});
    CHECK(rc::heatRamp(1.0) == rc::Rgb{253, 231, 37});
    CHECK(rc::heatRamp(2.0) == rc::heatRamp(1.0));
    std::set<std::tuple<int, int, int>> colours;
    for (int r = 1; r < rc::kMissReasons; ++r) {
        const rc::Rgb c = rc::missReasonColour(rc::MissReason(r));
        colours.insert({c.r, c.g, c.b});
    }
    CHECK(int(colours.size()) == rc::kMissReasons - 1);
}

TEST_CASE("The key names an overlay only when one of its shapes is drawn", "[view][legend]") {
    rc::SessionState s = session("trio", rc::CacheKind::Blocker, 64);
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    rc::ImageProjector proj(s.scene().camera, s.camera());
    proj.setClip({0, 0, 64, 64});
    const rc::LegendShown all{true, true, true, true};
    int checked = 0, shadows = 0;
    for (int i = 0; i < int(s.recorder().events().size()) && (checked < 5 || shadows == 0); ++i) {
        const auto f = rc::RayFocus::ofEvent(s, i);
        // Rays that hit, and shadow rays (whose hull ends at their light)
        if (!f || (f->hit < 0 && f->kind != rc::RayKind::Shadow) || f->deferred) continue;
        if (checked >= 5 && f->kind != rc::RayKind::Shadow) continue;
        const rc::FocusHull h = rc::hullOf(s, *f);
        if (!h.valid() || h.blockers.empty()) continue;
        rc::Selection sel;
        sel.event = i;
        const auto shapes = rc::focusShapes(s, *f, proj, {true, true});
        const auto keys = rc::legendEntries(s, sel, all, shapes);
        CHECK(hasText(keys, "blocker hull of origin and target"));
        CHECK(hasText(keys, f->kind == rc::RayKind::Shadow ? "target (the light)" : "target (cached object)"));
        CHECK(hasText(keys, "potential blockers"));
        CHECK(hasText(keys, "misses marked at path "));
        // The same focus with nothing drawn (every shape clipped away): no shape's entry
        const auto bare = rc::legendEntries(s, sel, all, {});
        CHECK_FALSE(hasText(bare, "blocker hull of origin and target"));
        CHECK_FALSE(hasText(bare, "target ("));
        CHECK_FALSE(hasText(bare, "potential blockers"));
        CHECK_FALSE(hasText(bare, "selected ray"));
        CHECK_FALSE(hasText(bare, "cylinder of safety"));
        CHECK(hasText(bare, "misses marked at path "));  // the markers are not focus shapes
        ++checked;
        shadows += f->kind == rc::RayKind::Shadow;
    }
    REQUIRE(checked > 0);
    REQUIRE(shadows > 0);  // a shadow ray's target is its light, and the key says so
    // A selected pixel is named, in the selection's colour
    rc::Selection sel;
    sel.pixel = 3 * 64 + 5;
    const auto keys = rc::focusEntries(s, sel, all, {});
    REQUIRE_FALSE(keys.empty());
    CHECK(keys.back().text == "selected pixel (5,3)");
    CHECK(keys.back().colour == rc::colours::kSelection);
}

TEST_CASE("Overlay names and aliases are read once, for the GUI, the page and the tours", "[view][registry]") {
    CHECK(rc::overlayNamed("cone") == "hull");
    CHECK(rc::overlayNamed("Blocker") == "hull");
    CHECK(rc::overlayNamed("bfs") == "frontier");
    CHECK(rc::overlayNamed("miss") == "misses");
    CHECK(rc::overlayNamed("cylinder") == "cylinder");
    CHECK(rc::overlayNamed("all").empty());
    CHECK(rc::overlayNamed("bogus").empty());
}
