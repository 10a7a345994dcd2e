// The viewer's Qt-free model: the shapes of the ray in focus come from the core, with
// their roles, so that every viewer draws the same overlays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <string>

#include "scene/builtin_scenes.h"
#include "view/compare_caption.h"
#include "view/miss_cause.h"
#include "view/overlay_layers.h"
#include "view/overlay_shapes.h"
#include "view/path_index.h"
#include "view/event_text.h"
#include "view/ray_tree_rows.h"
#include "view/session_state.h"

namespace {

int count(const std::vector<rc::OverlayShape>& shapes, rc::ShapeRole role) {
    return int(std::count_if(shapes.begin(), shapes.end(), [&](const rc::OverlayShape& s) { return s.role == role; }));
}

rc::SessionState session(const char* scene, rc::CacheKind cache, int size,
                         rc::OrderKind order = rc::OrderKind::Scanline) {
    rc::RenderOptions o;
    o.cache = cache;
    o.order = order;
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

TEST_CASE("The miss markers at a path mark exactly the pixels whose ray there missed, by reason", "[view]") {
    rc::SessionState s = session("cube:3", rc::CacheKind::Blocker, 48);
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    const std::vector<std::uint8_t> eye = rc::missLayer(s, 0);
    REQUIRE(eye.size() == std::size_t(48 * 48));
    // Counted from the event log (one eye ray a pixel, committed once), not the pixel chains
    std::size_t misses = 0, marked = 0;
    for (std::size_t i = 0; i < s.recorder().events().size(); ++i) {
        const rc::EventRecord& r = s.recorder().events()[i];
        if (r.node != 0 || r.deferred() || r.rayDecision() != rc::Decision::Miss) continue;
        ++misses;
        REQUIRE(eye[std::size_t(r.pixel)] == r.reason);
    }
    for (std::uint8_t m : eye) marked += m != 0;
    REQUIRE(misses > 0);
    REQUIRE(marked == misses);
}

TEST_CASE("The fill's region layer marks the region being filled, and nothing without a fill", "[view]") {
    rc::SessionState bfs = session("cube:3", rc::CacheKind::Blocker, 48, rc::OrderKind::BreadthFirst);
    REQUIRE(bfs.runUntil(rc::RunGoal::ToStep, 800));
    const std::vector<std::uint8_t> marks = rc::regionLayer(bfs);
    REQUIRE(std::count(marks.begin(), marks.end(), std::uint8_t(rc::RegionMark::Current)) > 0);
    rc::SessionState scan = session("cube:3", rc::CacheKind::Blocker, 48);
    REQUIRE(scan.runUntil(rc::RunGoal::ToStep, 800));
    const std::vector<std::uint8_t> none = rc::regionLayer(scan);
    REQUIRE(std::count(none.begin(), none.end(), std::uint8_t(0)) == 48 * 48);
}

TEST_CASE("The page's layers, read straight from the log, equal those drawn from a PathIndex", "[view]") {
    // The page builds no PathIndex (an entry a pixel); the Qt window draws from one
    rc::SessionState bfs = session("cube:3", rc::CacheKind::Blocker, 48, rc::OrderKind::BreadthFirst);
    int compared = 0;
    for (std::int64_t step : {300, 800, 2500, 6000}) {
        REQUIRE(bfs.runUntil(rc::RunGoal::ToStep, step));
        const rc::FrontierView f = bfs.session().order().frontier();
        if (f.path >= 0) {
            rc::PathIndex index;
            index.update(bfs.recorder(), bfs.serial(), f.path);
            REQUIRE(rc::regionLayer(bfs) == rc::regionLayer(index, 48, 48, f.region));
            ++compared;
        }
        for (int node : {0, 1, 2, 3}) {
            rc::PathIndex index;
            index.update(bfs.recorder(), bfs.serial(), node);
            REQUIRE(rc::missLayer(bfs, node) == rc::missLayer(index));
        }
    }
    REQUIRE(compared >= 3);
}

TEST_CASE("A ray chosen by pixel and path, the caption of the ray in focus, and the showcase ray", "[view]") {
    rc::SessionState s = session("trio", rc::CacheKind::Blocker, 64);
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    // The showcase: a reflection ray that hit an object, with blockers listed for its pair
    const int shown = rc::showcaseEvent(s);
    REQUIRE(shown >= 0);
    const rc::EventRecord& r = s.recorder().events()[std::size_t(shown)];
    REQUIRE(r.rayKind() == rc::RayKind::Reflection);
    REQUIRE(r.hit >= 0);
    // The same ray found again by its pixel and path (spaces and case aside)
    std::string why;
    const std::string path = s.session().cacheTree().label(r.node);
    std::string shouted = path;
    for (char& c : shouted) c = char(std::toupper(static_cast<unsigned char>(c)));
    REQUIRE(rc::eventAtPath(s, r.pixel, shouted, why) == shown);
    REQUIRE(why.empty());
    REQUIRE(rc::eventAtPath(s, r.pixel, "eye/nowhere", why) == -1);
    REQUIRE(why.find("its rays: eye") != std::string::npos);
    // The caption: the render, then the ray in focus, selected
    rc::Selection sel;
    sel.event = shown;
    const std::vector<std::string> lines = rc::focusCaption(s, sel);
    REQUIRE(lines.size() == 2);
    REQUIRE(lines[0] == "trio  blocker/scanline  64x64  step " + std::to_string(s.session().steps()));
    REQUIRE(lines[1].rfind("selected: pixel (" + std::to_string(r.pixel % 64) + "," + std::to_string(r.pixel / 64) +
                               ")  " + path + "  hit #" + std::to_string(r.hit),
                           0) == 0);
}

TEST_CASE("The compare caption gives the right render's tests and misses against the left's", "[view]") {
    rc::SessionState scan = session("cube:3", rc::CacheKind::Blocker, 48);
    rc::SessionState bfs = session("cube:3", rc::CacheKind::Blocker, 48, rc::OrderKind::BreadthFirst);
    REQUIRE(scan.runUntil(rc::RunGoal::ToEnd, 0));
    REQUIRE(bfs.runUntil(rc::RunGoal::ToEnd, 0));
    const auto& a = scan.session().counters();
    const auto& b = bfs.session().counters();
    REQUIRE(a.misses > 0);
    REQUIRE(b.misses != a.misses);
    const std::vector<std::string> lines = rc::compareCaption(scan, bfs);
    char want[160];
    std::snprintf(want, sizeof want, "misses %llu = %.2fx the left's %llu", (unsigned long long)b.misses,
                  double(b.misses) / double(a.misses), (unsigned long long)a.misses);
    INFO(want);
    REQUIRE(std::find(lines.begin(), lines.end(), std::string(want)) != lines.end());
    REQUIRE(lines.front().rfind("tests " + std::to_string(b.intersectionTests) + " = ", 0) == 0);
    // In step: nothing to catch up
    REQUIRE(lines.size() == 3);
}

TEST_CASE("Compared with an uncached render, the caption gives no ratio of misses", "[view]") {
    // The left has no cache, so no misses: "0.00x the left's 0" would read as a measurement
    rc::SessionState none = session("cube:3", rc::CacheKind::None, 48);
    rc::SessionState blocker = session("cube:3", rc::CacheKind::Blocker, 48, rc::OrderKind::BreadthFirst);
    REQUIRE(none.runUntil(rc::RunGoal::ToEnd, 0));
    REQUIRE(blocker.runUntil(rc::RunGoal::ToEnd, 0));
    REQUIRE(none.session().counters().misses == 0);
    const auto misses = blocker.session().counters().misses;
    REQUIRE(misses > 0);
    const std::vector<std::string> lines = rc::compareCaption(none, blocker);
    const std::string want = "misses " + std::to_string(misses) + " (the left has no cache misses)";
    INFO(want);
    REQUIRE(std::find(lines.begin(), lines.end(), want) != lines.end());
    for (const std::string& line : lines) REQUIRE(line.find("0.00x") == std::string::npos);
}

TEST_CASE("A pixel's ray tree: every ray it traced, each under the ray that spawned it", "[view]") {
    rc::SessionState s = session("cube:3", rc::CacheKind::Blocker, 48, rc::OrderKind::BreadthFirst);
    REQUIRE(s.runUntil(rc::RunGoal::ToEnd, 0));
    const rc::CacheTree& paths = s.session().cacheTree();
    int deepest = 0, deferred = 0, misses = 0;
    for (int px = 0; px < 48 * 48; ++px) {
        const std::vector<rc::RayTreeRow> rows = rc::rayTreeRows(s, px);
        REQUIRE(rows.size() == s.recorder().eventsOf(px).size());
        REQUIRE_FALSE(rows.empty());
        CHECK(rows.front().path == "eye");
        CHECK(rows.front().parent == -1);
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const rc::RayTreeRow& r = rows[k];
            const rc::EventRecord e = s.recorder().events()[std::size_t(r.event)];
            INFO("pixel " << px << " row " << k << " " << r.path);
            CHECK(r.path == paths.label(e.node));
            CHECK(r.tests == e.tests);
            CHECK(r.deferred == e.deferred());
            CHECK(r.hit == (r.deferred ? std::string("?") : rc::objectLabel(s.scene(), e.hit)));
            if (r.parent >= 0) {
                // Its parent came before it, is the committed ray of the path one step up
                REQUIRE(std::size_t(r.parent) < k);
                const rc::RayTreeRow& p = rows[std::size_t(r.parent)];
                CHECK_FALSE(p.deferred);
                CHECK(r.path.rfind(p.path + "/", 0) == 0);
                CHECK(r.depth == p.depth + 1);
            } else {
                CHECK(r.depth == 0);
            }
            deepest = std::max(deepest, r.depth);
            deferred += r.deferred;
            misses += r.miss;
        }
    }
    CHECK(deepest >= 2);   // cube:3 reflects: eye, reflection, its shadow rays
    CHECK(deferred > 0);   // breadth-first order defers some misses
    CHECK(misses > 0);
    CHECK(rc::rayTreeRows(s, -1).empty());
    CHECK(rc::objectLabel(s.scene(), -1) == "nothing");
    CHECK(rc::objectLabel(s.scene(), 0) == "#0 sphere");
}
