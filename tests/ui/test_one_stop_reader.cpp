// A tour stop is read once (view/viewer_settings.h): the Qt window's options (stopOptions)
// and the page's plan (rc::planOf, which its bindings hand to viewer.js) are both made
// from rc::stopSettings. At every stop of the shipped tours they agree on everything both
// front ends set; a bad stop is the same sentence in both.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "gui_options.h"
#include "view/tour.h"
#include "view/tour_stop.h"
#include "window_fixture.h"

using namespace rcgui;

namespace {

std::string s(std::string_view v) { return std::string(v); }

/// The window's options and the page's plan of one stop agree
void requireSame(const GuiOptions& o, const rc::StopPlan& p) {
    REQUIRE(o.scene.toStdString() == p.scene);
    REQUIRE(o.width == p.width);
    REQUIRE(o.height == p.height);
    REQUIRE(s(rc::toString(o.cache)) == p.cache);
    REQUIRE(s(rc::toString(o.order)) == p.order);
    REQUIRE(s(rc::toString(o.accel)) == p.accel);
    REQUIRE(o.band == p.band);
    REQUIRE(o.compare.has_value() == !p.compareCache.empty());
    if (o.compare) REQUIRE(toString(*o.compare).toStdString() == p.compareCache + ":" + p.compareOrder);
    REQUIRE(o.overlays.cylinder == p.has("cylinder"));
    REQUIRE(o.overlays.hull == p.has("hull"));
    REQUIRE(o.overlays.frontier == p.has("frontier"));
    REQUIRE(o.overlays.misses == p.has("misses"));
    REQUIRE(o.overlays.samples == p.has("samples"));
    REQUIRE(toString(o.heatmap).toStdString() == (p.heatmap.empty() ? "none" : p.heatmap));
    REQUIRE(std::max<qint64>(0, o.steps) == p.steps);
    REQUIRE(o.runTo.has_value() == !p.run.empty());
    if (o.runTo) REQUIRE((*o.runTo == rc::RunGoal::NextMiss) == (p.run == "next-miss"));
    REQUIRE((o.missReason == rc::MissReason::None ? "" : s(rc::toString(o.missReason))) == p.missReason);
    REQUIRE((o.select.x() >= 0) == p.select.has_value());
    if (p.select) {
        REQUIRE(o.select == QPoint(p.select->x, p.select->y));
        REQUIRE(o.selectPath.toStdString() == p.select->path);
    }
    REQUIRE(o.focus.isNull() == !p.focus);
    if (p.focus) {
        const std::vector<double> r{double(o.focus.left()), double(o.focus.top()), double(o.focus.right() + 1),
                                    double(o.focus.bottom() + 1)};
        REQUIRE(r == *p.focus);
    } else {
        REQUIRE(o.zoom == (p.zoom > 0 ? p.zoom : 1.0));
    }
}

}  // namespace

TEST_CASE("Every stop of both tours: the window and the page take one reading of it", "[gui][tour][stop]") {
    int stops = 0;
    for (const char* name : {"hanrahan86.json", "debugging.json"}) {
        const rc::Tour tour = testing::shippedTour(name);
        const std::vector<GuiOptions> window = testing::stopOptionsOf(tour);
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            INFO(name << " stop " << k);
            requireSame(window[std::size_t(k - 1)], rc::planOf(tour, k));
            ++stops;
        }
    }
    REQUIRE(stops >= 16);  // 18 when this was written: the loops ran over both tours
}

TEST_CASE("A bad stop is the same sentence in the window and the page", "[gui][tour][stop]") {
    const rc::Tour tour = rc::parseTour(R"({"stops": [
  {"title": "Cache", "caption": "c.", "scene": "pair", "cache": "lru"},
  {"title": "Select", "caption": "c.", "scene": "pair", "select": "3;4"},
  {"title": "Overlays", "caption": "c.", "scene": "pair", "overlays": ["cone", "sparkles"]},
  {"title": "Heatmap", "caption": "c.", "scene": "pair", "heatmap": "hit-rate"},
  {"title": "Size", "caption": "c.", "scene": "pair", "width": 100000},
  {"title": "Run", "caption": "c.", "scene": "pair", "run": "next-hit"},
  {"title": "Zoom", "caption": "c.", "scene": "pair", "zoom": "nan"}]})",
                                        "bad.json");
    const char* flags[] = {"--cache", "--select", "--overlays", "--heatmap", "--width", "--run", "--zoom"};
    for (int k = 1; k <= int(tour.stops.size()); ++k) {
        INFO("stop " << k);
        QString why;
        REQUIRE_FALSE(stopOptions(tour, k, GuiOptions{}, why));
        REQUIRE(why.startsWith(QString("bad.json:%1:3: stop %2 (").arg(k + 1).arg(k)));
        REQUIRE(why.contains(flags[k - 1]));  // the flag's name, as on the command line
        try {
            (void)rc::planOf(tour, k);
            FAIL("the page's plan read a bad stop");
        } catch (const rc::TourError& e) {
            REQUIRE(e.what() == why.toStdString());
        }
    }
}
