// The viewer's Qt-free model: the shapes of the ray in focus come from the core, with
// their roles, so that every viewer draws the same overlays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include "scene/builtin_scenes.h"
#include "view/miss_cause.h"
#include "view/overlay_shapes.h"
#include "view/session_state.h"

namespace {

int count(const std::vector<rc::OverlayShape>& shapes, rc::ShapeRole role) {
    return int(std::count_if(shapes.begin(), shapes.end(), [&](const rc::OverlayShape& s) { return s.role == role; }));
}

rc::SessionState session(const char* scene, rc::CacheKind cache, int size) {
    rc::RenderOptions o;
    o.cache = cache;
    o.order = rc::OrderKind::Scanline;
    o.width = o.height = size;
    return rc::SessionState({std::make_shared<const rc::Scene>(rc::loadScene(scene)), o});
}

}  // namespace

TEST_CASE("The shapes of a ray with a blocker list: hull, origin, target and each kept blocker", "[view]") {
    rc::SessionState s = session("trio", rc::CacheKind::Blocker, 64);
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    rc::ImageProjector proj(s.scene().camera, s.camera());
    proj.setClip({0, 0, 64, 64});
    // Every hit ray whose pair lists potential blockers: one shape per kept blocker
    int checked = 0;
    for (int i = 0; i < int(s.recorder().events().size()) && checked < 20; ++i) {
        const auto f = rc::RayFocus::ofEvent(s, i);
        if (!f || f->hit < 0 || f->deferred) continue;
        const rc::FocusHull h = rc::hullOf(s, *f);
        if (!h.valid() || h.blockers.empty()) continue;
        const auto shapes = rc::focusShapes(s, *f, proj, {false, true});
        REQUIRE(count(shapes, rc::ShapeRole::Hull) == 1);
        REQUIRE(count(shapes, rc::ShapeRole::Origin) == 1);
        REQUIRE(count(shapes, rc::ShapeRole::Blocker) == int(h.blockers.size()));
        REQUIRE(count(shapes, rc::ShapeRole::Ray) == 1);
        REQUIRE(count(shapes, rc::ShapeRole::Cylinder) + count(shapes, rc::ShapeRole::CachedCylinder) == 0);
        for (const rc::OverlayShape& shape : shapes) {
            // Outlines stay within the clip rectangle (with rounding)
            for (const rc::ImagePoint& p : shape.outline) {
                REQUIRE(p.x >= -1e-6);
                REQUIRE(p.x <= 64 + 1e-6);
            }
            if (shape.role == rc::ShapeRole::Blocker) REQUIRE(shape.label == "blocker #" + std::to_string(shape.object));
        }
        ++checked;
    }
    REQUIRE(checked > 0);
}

TEST_CASE("A ray that left its cylinder shows the cylinder it left", "[view]") {
    rc::SessionState s = session("cube:4", rc::CacheKind::Cylinder, 64);
    s.setMissFilter(rc::MissReason::LeftCylinder);
    REQUIRE(s.runUntil(rc::RunGoal::NextMiss, 0));
    REQUIRE(s.stopEvent() >= 0);
    const auto f = rc::RayFocus::ofEvent(s, s.stopEvent());
    REQUIRE(f);
    REQUIRE(f->reason == rc::MissReason::LeftCylinder);
    rc::ImageProjector proj(s.scene().camera, s.camera());
    const auto shapes = rc::focusShapes(s, *f, proj, {true, false});
    REQUIRE(count(shapes, rc::ShapeRole::CylinderLeft) == 1);
    REQUIRE(count(shapes, rc::ShapeRole::Cylinder) + count(shapes, rc::ShapeRole::CachedCylinder) == 1);
    // Nothing asked for, nothing made
    REQUIRE(rc::focusShapes(s, *f, proj, {false, false}).empty());
}
