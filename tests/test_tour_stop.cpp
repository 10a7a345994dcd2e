// A tour stop applied (view/tour_stop.h): its settings read once (view/viewer_settings.h) into what a viewer sets,
// and its rays applied to a render, as the web page does through its bindings.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "order/ray_order.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"
#include "search/cache_strategy.h"
#include "view/heatmap.h"
#include "view/palette.h"
#include "view/ray_focus.h"
#include "view/tour_stop.h"

namespace {

const rc::Tour kTour = rc::parseTour(R"({"stops": [
  {"title": "A", "caption": "a.", "scene": "pair", "width": 32, "height": 32, "cache": "blocker+",
   "order": "progressive", "band": 0, "compare": "blocker:scanline", "overlays": ["cone", "misses"],
   "heatmap": "tests", "steps": 1500, "select": "16,16:eye", "focus": "4,4,20,20"},
  {"title": "B", "caption": "b.", "scene": "pair", "width": 32, "height": 32, "cache": "blocker",
   "order": "scanline", "run": "next-miss", "scene-view": "side", "panels": ["ray-tree", "statistics"], "spp": 4,
   "overlays": ["all"]},
  {"title": "C", "caption": "c.", "scene": "pair", "width": 32, "height": 32, "scene-view": "along", "steps": 2000}
]})", "/some/where/t.json");

std::unique_ptr<rc::SessionState> stateOf(const rc::StopPlan& p) {
    rc::SessionConfig c;
    c.scene = std::make_shared<const rc::Scene>(rc::loadScene(p.scene, 1986));
    c.options.width = p.width;
    c.options.height = p.height;
    c.options.cache = *rc::parseCacheKind(p.cache);
    c.options.order = *rc::parseOrderKind(p.order);
    c.options.band = p.band;
    return std::make_unique<rc::SessionState>(std::move(c));
}

}  // namespace

TEST_CASE("a stop's settings are read once into what a viewer sets", "[tour][view]") {
    const rc::StopPlan a = rc::planOf(kTour, 1);
    REQUIRE(a.scene == "pair");  // a built-in name stays as it is
    REQUIRE(a.cache == "blocker+");
    REQUIRE(a.order == "progressive");
    REQUIRE(a.band == 0);
    REQUIRE(a.compareCache == "blocker");
    REQUIRE(a.compareOrder == "scanline");
    REQUIRE(a.overlays == std::vector<std::string>{"hull", "misses"});  // cone is the hull's alias
    REQUIRE(a.heatmap == "tests");
    REQUIRE(a.select);
    REQUIRE(a.select->x == 16);
    REQUIRE(a.select->path == "eye");
    REQUIRE(a.focus == std::vector<double>{4, 4, 20, 20});
    REQUIRE(a.qtOnly.empty());
    REQUIRE_FALSE(a.showcase);

    const rc::StopPlan b = rc::planOf(kTour, 2);
    REQUIRE(b.band == -1);
    REQUIRE(b.compareCache.empty());
    REQUIRE(b.run == "next-miss");
    REQUIRE(b.has("hull"));
    REQUIRE(b.has("cylinder"));
    REQUIRE(b.has("frontier"));
    REQUIRE_FALSE(b.showcase);  // it runs to a miss, which comes in focus
    // The page shows the ray tree as well: the note leaves that panel out
    REQUIRE(b.qtOnly == std::vector<std::string>{"the scene view (side)", "the panels (statistics)", "--spp",
                                                  "the sample rays"});
    REQUIRE(rc::planOf(kTour, 3).showcase);
    REQUIRE_THROWS_AS(rc::planOf(kTour, 4), rc::TourError);
}

TEST_CASE("a stop's rays are applied: its steps, its run to a miss, its selection", "[tour][view]") {
    const rc::StopPlan a = rc::planOf(kTour, 1);
    const auto state = stateOf(a);
    rc::SessionState& s = *state;
    const rc::StopApplied applied = rc::applyStopRays(s, a);
    REQUIRE(s.session().steps() == 1500);
    REQUIRE(applied.notes.empty());
    REQUIRE(applied.selection.pixel == 16 * 32 + 16);
    REQUIRE(applied.selection.event >= 0);
    REQUIRE(s.recorder().events()[std::size_t(applied.selection.event)].pixel == 16 * 32 + 16);

    const rc::StopPlan b = rc::planOf(kTour, 2);
    const auto tState = stateOf(b);
    rc::SessionState& t = *tState;
    const rc::StopApplied miss = rc::applyStopRays(t, b);
    REQUIRE(miss.notes.empty());
    REQUIRE(miss.selection.event == t.stopEvent());
    const auto f = rc::RayFocus::ofEvent(t, miss.selection.event);
    REQUIRE(f);
    REQUIRE(f->decision == rc::Decision::Miss);
    REQUIRE(miss.selection.pixel == f->pixel);

    rc::StopPlan outside = a;
    outside.select = rc::StopSelect{40, 3, ""};
    const auto uState = stateOf(outside);
    rc::SessionState& u = *uState;
    const rc::StopApplied refused = rc::applyStopRays(u, outside);
    REQUIRE(refused.notes.size() == 1);
    REQUIRE(refused.notes[0].find("outside the 32x32 image") != std::string::npos);
}

TEST_CASE("the tests heatmap: a log scale to the top, untraced pixels black", "[view][heatmap]") {
    const rc::StopPlan a = rc::planOf(kTour, 1);
    const auto state = stateOf(a);
    rc::SessionState& s = *state;
    s.runUntil(rc::RunGoal::ToStep, 300);
    const rc::TraceRecorder& rec = s.recorder();
    const double top = rc::testsTop(rec);
    REQUIRE(top >= 1);
    int traced = -1, untraced = -1;
    for (int px = 0; px < 32 * 32; ++px) (rec.firstVisit(px) >= 0 ? traced : untraced) = px;
    REQUIRE(traced >= 0);
    REQUIRE(untraced >= 0);
    REQUIRE_FALSE(rc::testsHeat(rec, untraced, top));
    REQUIRE(*rc::testsHeat(rec, traced, top) == Approx(std::log1p(rec.testsAt(traced)) / std::log1p(top)));
    const std::vector<std::uint8_t> rgba = rc::testsHeatmapRgba(rec, top);
    REQUIRE(rgba.size() == 32 * 32 * 4);
    const rc::Rgb c = rc::heatRamp(*rc::testsHeat(rec, traced, top));
    REQUIRE(rgba[std::size_t(traced) * 4] == c.r);
    REQUIRE(rgba[std::size_t(traced) * 4 + 2] == c.b);
    REQUIRE(rgba[std::size_t(untraced) * 4] == 0);
    REQUIRE(rgba[std::size_t(untraced) * 4 + 3] == 255);
}

TEST_CASE("a stop is read by the command line's definitions, with the CLI's limits", "[tour][view][stop]") {
    const std::string largest = std::to_string(rc::NffLimits::maxResolution);
    const rc::Tour tour = rc::parseTour(R"({"stops": [
  {"title": "Fine", "caption": "c.", "scene": "pair", "width": )" + largest + R"(, "overlays": ["cone", "none", "miss"],
   "orbit": "-30,10"},
  {"title": "Wide", "caption": "c.", "scene": "pair", "width": )" + std::to_string(rc::NffLimits::maxResolution + 1) + R"(},
  {"title": "Bad", "caption": "c.", "scene": "pair", "focus": "4,4,2,2"}]})", "t.json");
    const rc::ViewerSettings fine = rc::stopSettings(tour, 1);
    REQUIRE(fine.width == int(rc::NffLimits::maxResolution));
    REQUIRE(fine.overlays == std::vector<std::string>{"misses"});  // none clears what came before it
    REQUIRE(fine.orbitYaw == -30);  // a value may start with '-'
    // What the stop reads is what the same flags on a command line read
    rc::ViewerSettings flags;
    REQUIRE(rc::readSettings(rc::stopArguments(tour, 1), flags).empty());
    REQUIRE(flags.width == fine.width);
    REQUIRE(flags.overlays == fine.overlays);
    // A bad stop is a sentence at its place, naming the flag
    for (int k : {2, 3}) {
        try {
            (void)rc::planOf(tour, k);
            FAIL("stop " << k << " was read");
        } catch (const rc::TourError& e) {
            const std::string what = e.what();
            INFO(what);
            REQUIRE(what.rfind("t.json:" + std::to_string(k + 2) + ":3: stop " + std::to_string(k) + " (", 0) == 0);
            REQUIRE(what.find(k == 2 ? "--width" : "--focus must be x0,y0,x1,y1") != std::string::npos);
        }
    }
}

TEST_CASE("the keys a stop may hold are the settings the one reader declares", "[tour][view][stop]") {
    const std::vector<std::string>& names = rc::tourSettingNames();
    auto has = [&names](const std::string& n) { return std::find(names.begin(), names.end(), n) != names.end(); };
    for (const char* n : {"scene", "cache", "width", "spp", "seed", "overlays", "select", "zoom", "scene-view", "orbit",
                          "focus", "panels", "miss-reason", "run"})
        REQUIRE(has(n));
    for (const char* n : {"help", "screenshot", "window", "tour", "stop"}) REQUIRE_FALSE(has(n));  // the window's own
    // A window-only flag in a stop is refused by the tour's parser
    REQUIRE_THROWS_WITH(rc::parseTour(R"({"stops": [{"title": "T", "caption": "c.", "scene": "pair", "window": "9x9"}]})", "t.json"),
                        Catch::Contains("unknown stop setting 'window'"));
}
