// GUI tests of the tour player: the next stop rendered ahead while this one is shown and
// taken as it is when the stop is reached, and a stop whose render is the one shown going
// on with it. No wall-clock time is asserted: what is asserted is which renders are built.
#include <catch2/catch.hpp>

#include <functional>

#include <QApplication>
#include <QElapsedTimer>

#include "main_window.h"
#include "tour_player.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::stateOf;

namespace {

/// Runs the event loop until `done` holds (the test fails after a minute without).
void waitUntil(const std::function<bool()>& done) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < 60000) QApplication::processEvents(QEventLoop::AllEvents, 20);
    REQUIRE(done());
}

/// A small stop: `pair` at 64x64 with `cache` and `order`, its first `steps` rays.
GuiOptions smallStop(rc::CacheKind cache, rc::OrderKind order, qint64 steps) {
    GuiOptions o;
    o.scene = "pair";
    o.width = o.height = 64;
    o.cache = cache;
    o.order = order;
    o.steps = steps;
    o.panels = QStringList();
    return o;
}

/// A tour of `stops`, each with a title.
rc::Tour tourOf(std::size_t stops) {
    rc::Tour t;
    t.title = "test";
    for (std::size_t i = 0; i < stops; ++i) t.stops.push_back({"stop " + std::to_string(i + 1), "A stop.", "", {}, {}, 0, 0, 1, 1});
    return t;
}

/// The window's picture as the core drew it.
std::vector<std::uint8_t> pixels(const rc::SessionState& s) { return s.session().image().rgb8(); }

/// `w` as raycache-gui shows it: renders built on workers (so tours render ahead), at a
/// projector's size; any error fails the test.
void makeLive(MainWindow& w) {
    w.setErrorReporter([](const QString& t, const QString& m) { FAIL((t + ": " + m).toStdString()); });
    w.setWorkerSessions(true);
    showAt(w, 1280, 720);
}

/// Nothing of the window runs: neither its renders nor a render made ahead.
bool idle(MainWindow& w) {
    return !w.controller().busy() && !w.compareController().busy() && !w.tourPlayer().aheadBusy() && w.controller().state();
}

}  // namespace

TEST_CASE("The next stop is rendered ahead, and reaching it starts no new render", "[gui][tour][ahead]") {
    MainWindow w;
    makeLive(w);
    GuiOptions second = smallStop(rc::CacheKind::None, rc::OrderKind::Scanline, 3000);
    second.compare = CompareChoice{rc::CacheKind::Blocker, rc::OrderKind::BreadthFirst};
    w.setTour(tourOf(2), {smallStop(rc::CacheKind::Blocker, rc::OrderKind::BreadthFirst, 2000), second});
    const bool ahead = GENERATE(true, false);
    w.tourPlayer().setAhead(ahead);
    REQUIRE(w.goToStop(1));
    waitUntil([&] { return idle(w) && w.tourPlayer().lastPictureMs() >= 0 && (!ahead || w.tourPlayer().aheadStop() == 2); });
    const int built = w.rendersBuilt();
    REQUIRE(w.goToStop(2));
    waitUntil([&] { return idle(w) && w.tourPlayer().lastPictureMs() >= 0; });
    if (ahead) {
        // Stop 2 builds no render of its own: both, its own and the compared one, come from ahead
        REQUIRE(w.rendersBuilt() == built);
        REQUIRE(w.tourPlayer().aheadTaken() == 2);
    } else {
        REQUIRE(w.rendersBuilt() == built + 2);
        REQUIRE(w.tourPlayer().aheadTaken() == 0);
    }
    // Either way, the very render the stop asks for: its steps and its pixels
    rc::SessionState& s = stateOf(w);
    REQUIRE(s.session().steps() == 3000);
    REQUIRE(s.session().options().cache == rc::CacheKind::None);
    rc::RenderOptions ro = renderOptionsOf(second);
    rc::SessionState fresh({s.config().scene, ro});
    fresh.runUntil(rc::RunGoal::ToStep, 3000);
    REQUIRE(pixels(s) == pixels(fresh));
    REQUIRE(w.compareController().state() != nullptr);
    REQUIRE(w.compareController().state()->session().steps() == 3000);
    REQUIRE(w.compareController().state()->session().options().cache == rc::CacheKind::Blocker);
}

TEST_CASE("A stop whose render is the one shown goes on with it", "[gui][tour][ahead]") {
    MainWindow w;
    makeLive(w);
    GuiOptions later = smallStop(rc::CacheKind::Blocker, rc::OrderKind::Scanline, 4000);
    later.overlays = *Overlays::parse("cylinder");
    w.setTour(tourOf(3), {smallStop(rc::CacheKind::Blocker, rc::OrderKind::Scanline, 1500), later,
                          smallStop(rc::CacheKind::Blocker, rc::OrderKind::Scanline, 1000)});
    REQUIRE(w.goToStop(1));
    waitUntil([&] { return idle(w) && w.tourPlayer().lastPictureMs() >= 0; });
    // The next stop's render is this one's: nothing is made ahead
    REQUIRE(w.tourPlayer().aheadStop() == 0);
    const rc::SessionState* first = w.controller().state();
    const int built = w.rendersBuilt();
    for (const auto& [stop, steps] : {std::pair{2, 4000}, std::pair{3, 1000}}) {
        // Onwards, then back: the same render, traced on or replayed from a checkpoint
        REQUIRE(w.goToStop(stop));
        waitUntil([&] { return idle(w) && w.tourPlayer().lastPictureMs() >= 0; });
        REQUIRE(w.rendersBuilt() == built);
        REQUIRE(w.controller().state() == first);
        REQUIRE(stateOf(w).session().steps() == steps);
    }
}
