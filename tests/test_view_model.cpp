// The viewer's Qt-free model: the shapes of the ray in focus come from the core, with
// their roles, so that every viewer draws the same overlays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include "scene/builtin_scenes.h"
#include "view/miss_cause.h"
#include "view/overlay_shapes.h"
#include "view/path_index.h"
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

TEST_CASE("The path index gives every pixel's event at a path, read in parts as the log grows", "[view]") {
    rc::SessionState s = session("trio", rc::CacheKind::Blocker, 48);
    const int pixels = 48 * 48;
    rc::PathIndex index;
    // Halfway: the index agrees with the recorder's own walk of each pixel's events
    REQUIRE(s.runUntil(rc::RunGoal::ToStep, 1000));
    auto agrees = [&](const rc::PathIndex& ix, int node) {
        int found = 0;
        for (int px = 0; px < pixels; ++px) {
            REQUIRE(ix.eventAt(px) == s.recorder().eventAt(px, node));
            if (ix.eventAt(px) >= 0) {
                const rc::EventRecord& e = s.recorder().events()[std::size_t(ix.eventAt(px))];
                REQUIRE(ix.at(px).region == e.region);
                REQUIRE(ix.at(px).decision == e.decision);
                REQUIRE(ix.at(px).reason == e.reason);
                ++found;
            }
        }
        return found;
    };
    rc::PathIndex::Update u = index.update(s.recorder(), s.serial(), 0);
    REQUIRE(u.rebuilt);
    REQUIRE(u.complete);
    const int half = agrees(index, 0);
    REQUIRE(half > 0);
    REQUIRE(half < pixels);
    // To the end: only the new events are read, and the pixels they reach are named
    const std::size_t readBefore = index.read();
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    u = index.update(s.recorder(), s.serial(), 0);
    REQUIRE(!u.rebuilt);
    REQUIRE(index.read() == s.recorder().events().size());
    REQUIRE(int(u.pixels.size()) >= pixels - half);
    REQUIRE(readBefore < index.read());
    REQUIRE(agrees(index, 0) == pixels);
    // Another path starts over; a budget reads the log in parts, each a budget long
    rc::PathIndex parts;
    const std::size_t budget = s.recorder().events().size() / 5 + 1;
    int updates = 0;
    do {
        u = parts.update(s.recorder(), s.serial(), 1, budget);
        REQUIRE(u.rebuilt == (updates == 0));
        ++updates;
        REQUIRE(parts.read() == std::min(s.recorder().events().size(), budget * std::size_t(updates)));
    } while (!u.complete);
    REQUIRE(updates == 5);
    REQUIRE(agrees(parts, 1) > 0);
    // A state taken back (a new serial) starts over
    s.rewindTo(100);
    u = parts.update(s.recorder(), s.serial(), 1);
    REQUIRE(u.rebuilt);
    agrees(parts, 1);
}
