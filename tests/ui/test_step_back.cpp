// GUI tests: Step back and Go to step backwards go back to a checkpoint and replay a few
// steps, and leave the window as stepping forwards to the same step does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>

#include <QApplication>

#include "main_window.h"
#include "window_fixture.h"
#include "view/ray_focus.h"
#include "stats_panel.h"
#include "view/step_checkpoints.h"

using namespace rcgui;

namespace {

/// A window on cube:5, 256x256, blocker+ cache (or another), breadth-first: about 180,000
/// steps, several checkpoint spacings.
struct Window {
    MainWindow w;
    explicit Window(rc::CacheKind cache = rc::CacheKind::BlockerPlus, rc::OrderKind order = rc::OrderKind::BreadthFirst) {
        w.setCache(cache);
        w.setOrder(order);
        REQUIRE(w.loadScene("cube:5"));
        w.setImageSize(256, 256);
        rcgui::testing::showAt(w, 1000, 800);
    }
    rc::SessionState& state() { return rcgui::testing::stateOf(w); }
    void goTo(std::int64_t step) {
        w.goToStep(step);
        w.controller().wait();
        REQUIRE(state().session().steps() == step);
        w.refresh();
    }
};

/// What the window shows: image, statistics, the ray in focus, the recorder's tallies.
void requireSame(Window& a, Window& b) {
    const rc::SessionState& s = a.state();
    const rc::SessionState& t = b.state();
    REQUIRE(s.session().steps() == t.session().steps());
    REQUIRE(SessionController::imageOf(s) == SessionController::imageOf(t));
    REQUIRE(s.session().counters() == t.session().counters());
    REQUIRE(a.w.statsPanel()->summaryText() == b.w.statsPanel()->summaryText());
    // The ray in focus
    const auto f = rc::RayFocus::of(s, a.w.selection()), g = rc::RayFocus::of(t, b.w.selection());
    REQUIRE(f.has_value() == g.has_value());
    if (f) {
        REQUIRE(f->event == g->event);
        REQUIRE(f->pixel == g->pixel);
        REQUIRE(f->node == g->node);
        REQUIRE(f->hit == g->hit);
        REQUIRE(f->t == g->t);
        REQUIRE(f->decision == g->decision);
        REQUIRE(f->reason == g->reason);
        REQUIRE(f->tests == g->tests);
    }
    // The recorder, event by event and pixel by pixel
    const rc::TraceRecorder& r = s.recorder();
    const rc::TraceRecorder& q = t.recorder();
    REQUIRE(r.events().size() == q.events().size());
    REQUIRE(r.misses().size() == q.misses().size());
    int differ = 0;
    for (int p = 0; p < s.width() * s.height(); ++p)
        if (r.lastEventOf(p) != q.lastEventOf(p) || r.testsAt(p) != q.testsAt(p) || r.hitsAt(p) != q.hitsAt(p) ||
            r.missesAt(p) != q.missesAt(p) || r.firstVisit(p) != q.firstVisit(p) ||
            r.missReasonAt(p) != q.missReasonAt(p))
            ++differ;
    REQUIRE(differ == 0);
    REQUIRE(r.samples().size() == q.samples().size());
    for (std::size_t i = 0; i < r.samples().size(); ++i) {
        REQUIRE(r.samples()[i].step == q.samples()[i].step);
        REQUIRE(r.samples()[i].tests == q.samples()[i].tests);
    }
    const rc::BeamTreeStats beams = s.beams().build(), direct = t.beams().build();
    REQUIRE(beams.nodes == direct.nodes);
    REQUIRE(beams.averageRayTreeSize == direct.averageRayTreeSize);
}

}  // namespace

TEST_CASE("Step back late in a render replays fewer steps than a checkpoint spacing", "[gui][step]") {
    for (rc::OrderKind order : {rc::OrderKind::BreadthFirst, rc::OrderKind::Scanline}) {
        Window back(rc::CacheKind::BlockerPlus, order);
        back.w.runToEnd();
        back.w.controller().wait();
        const std::int64_t end = back.state().session().steps();
        const std::int64_t every = back.state().checkpoints().every();
        REQUIRE(end > 4 * every);  // late: many spacings in
        // Three steps back from the end, each replaying from a checkpoint
        for (int i = 1; i <= 3; ++i) {
            back.w.stepBack();
            back.w.controller().wait();
            REQUIRE(back.state().session().steps() == end - i);
            REQUIRE(back.w.controller().replayed() < every);
            REQUIRE(back.w.controller().replayed() == (end - i) % every);
        }
        back.w.refresh();
        Window forward(rc::CacheKind::BlockerPlus, order);
        forward.goTo(end - 3);
        requireSame(back, forward);
    }
}

TEST_CASE("Go to step backwards goes back to a checkpoint, and on again is the render as it was", "[gui][step]") {
    Window w(rc::CacheKind::Blocker);
    const std::int64_t every = w.state().checkpoints().every();
    const std::int64_t late = 4 * every + 1234, early = every / 3;
    w.goTo(late);
    REQUIRE(w.state().checkpoints().size() == 5);  // steps 0, every, ..., 4 every
    // Far back: less than the way is replayed (here from step 0)
    w.goTo(early);
    REQUIRE(w.w.controller().replayed() == early);
    Window forward(rc::CacheKind::Blocker);
    forward.goTo(early);
    requireSame(w, forward);
    // Forwards again from there, then back a step onto a checkpoint
    w.goTo(3 * every + 1);
    w.goTo(3 * every);
    REQUIRE(w.w.controller().replayed() == 0);
    forward.goTo(3 * every);
    requireSame(w, forward);
}

TEST_CASE("Step back with a pixel selected keeps the same ray in focus as stepping there", "[gui][step]") {
    Window back;
    const std::int64_t at = back.state().checkpoints().every() * 2 + 5000;
    back.goTo(at - 100);  // a pixel traced before the step gone back to
    const int pixel = back.state().recorder().lastCommitted()->task.pixel;
    back.goTo(at);
    back.w.selectPixel(pixel % 256, pixel / 256);
    back.w.stepBack();
    back.w.controller().wait();
    back.w.refresh();
    REQUIRE(back.w.controller().replayed() < back.state().checkpoints().every());
    Window forward;
    forward.goTo(at - 1);
    forward.w.selectPixel(pixel % 256, pixel / 256);
    forward.w.refresh();
    REQUIRE(rc::RayFocus::of(back.state(), back.w.selection())->selected);
    requireSame(back, forward);
}

TEST_CASE("Checkpoints thin out geometrically behind the render", "[gui][step]") {
    rc::StepCheckpoints list(1);
    for (std::int64_t m = 0; m <= 1000; ++m) {
        rc::StepCheckpoint c;
        c.session.steps = m;
        list.add(std::move(c));
        const std::vector<std::int64_t> kept = list.steps();
        REQUIRE(kept.front() == 0);
        REQUIRE(kept.back() == m);
        // Few: about two per doubling of the distance
        REQUIRE(kept.size() <= std::size_t(2 * std::bit_width(std::uint64_t(m)) + 3));
        // The gap before a checkpoint at distance d from the newest is at most d / 2 (the
        // last ones one apart)
        for (std::size_t i = 1; i < kept.size(); ++i)
            REQUIRE(kept[i] - kept[i - 1] <= std::max<std::int64_t>(1, (m - kept[i - 1]) / 2));
    }
    // Going back drops the later ones
    const rc::StepCheckpoint* c = list.backTo(700);
    REQUIRE(c != nullptr);
    REQUIRE(c->steps() <= 700);
    REQUIRE(c->steps() > 700 - 300 / 2);
    REQUIRE(list.steps().back() == c->steps());
}
