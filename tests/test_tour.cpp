// Tours: the JSON a lecture is written in, read with positions for every error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>

#include "scene/builtin_scenes.h"
#include "view/claim.h"
#include "view/tour.h"

namespace {

/// The message of the TourError that parsing `text` throws ("" if it parses).
std::string errorOf(const std::string& text) {
    try {
        rc::parseTour(text, "t.json");
    } catch (const rc::TourError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST_CASE("a tour's stops keep their order, text and settings", "[tour]") {
    const rc::Tour t = rc::parseTour(R"({
  "title": "Two stops",
  "stops": [
    {"title": "A", "caption": "First.", "scene": "cube:4", "steps": 2000, "compare": false,
     "overlays": ["cylinder", "cone"], "zoom": 2.5},
    {"title": "B", "caption": "\"Quoted\" words.", "scene": "trio", "scene-view": true, "compare": "none:scanline"}
  ]
})",
                                     "t.json");
    REQUIRE(t.title == "Two stops");
    REQUIRE(t.stops.size() == 2);
    const rc::TourStop& a = t.stops[0];
    REQUIRE(a.title == "A");
    REQUIRE(a.caption == "First.");
    REQUIRE(a.value("scene") == "cube:4");
    REQUIRE(a.value("steps") == "2000");
    REQUIRE(a.value("overlays") == "cylinder,cone");
    REQUIRE(a.value("zoom") == "2.5");
    REQUIRE(a.value("heatmap", "none") == "none");
    REQUIRE(a.line == 4);
    REQUIRE(a.column == 5);
    // Settings keep the position of their key
    REQUIRE(a.settings[1].key == "steps");
    REQUIRE(a.settings[1].line == 4);
    REQUIRE(a.settings[1].column == 60);
    REQUIRE(t.stops[1].caption == "\"Quoted\" words.");
    // true is a switch (no value); false leaves the setting out
    REQUIRE(t.stops[1].settings[1].key == "scene-view");
    REQUIRE(t.stops[1].settings[1].value.empty());
    REQUIRE(a.value("compare", "absent") == "absent");
}

TEST_CASE("a bad tour is reported at file:line:column", "[tour]") {
    // Not JSON: the position of the bad token
    REQUIRE(errorOf("{\n  \"stops\": [\n    {\"title\": \"A\",, }\n  ]\n}").rfind("t.json:3:19: not valid JSON", 0) == 0);
    // An unknown setting: at its key
    REQUIRE(errorOf("{\"stops\": [\n {\"title\": \"A\", \"caption\": \"c\", \"scene\": \"cube:3\",\n  \"cahce\": \"none\"}]}")
                .rfind("t.json:3:3: unknown stop setting 'cahce'", 0) == 0);
    // A stop without its caption: at the stop
    REQUIRE(errorOf("{\"stops\": [\n  {\"title\": \"A\", \"scene\": \"cube:3\"}]}") == "t.json:2:3: stop 1 has no 'caption'");
    REQUIRE(errorOf("{\"stops\": [{\"title\": \"A\", \"caption\": \"c\"}]}") == "t.json:1:12: stop 1 has no 'scene'");
    REQUIRE(errorOf("{\"stops\": []}").find("at least one stop") != std::string::npos);
    REQUIRE(errorOf("[]").find("not an array") != std::string::npos);
    REQUIRE(errorOf("{\"stops\": [{\"title\": \"A\", \"caption\": \"c\", \"scene\": null}]}").find("not null") !=
            std::string::npos);
    REQUIRE(errorOf("{\"stops\": [{\"title\": \"A\", \"caption\": \"c\", \"scene\": \"x\", \"scene\": \"y\"}]}")
                .find("sets 'scene' twice") != std::string::npos);
    REQUIRE(errorOf("{\"stops\": [{\"title\": \"A\", \"caption\": \"c\", \"scene\": {\"x\": 1}}]}").find("'scene' must") !=
            std::string::npos);
    REQUIRE(errorOf("{\"title\": \"T\"}") == "t.json:1:14: a tour needs a 'stops' array");
    try {
        rc::loadTour("no/such/tour.json");
        FAIL("a missing file was read");
    } catch (const rc::TourError& e) {
        REQUIRE(std::string(e.what()) == "no/such/tour.json:0:0: cannot read the tour file");
    }
}

TEST_CASE("the shipped tours parse", "[tour]") {
    const std::filesystem::path tours = std::filesystem::path(RAYCACHE_SCENES_DIR).parent_path() / "tours";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(tours)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        const rc::Tour t = rc::loadTour(entry.path().string());
        INFO(entry.path().string());
        REQUIRE(!t.title.empty());
        REQUIRE(!t.stops.empty());
        // Every stop's scene, pixel, path, focus and claims hold, as when a front end opens it
        REQUIRE_NOTHROW(rc::checkTour(t));
    }
    REQUIRE(files >= 2);
}

TEST_CASE("a tour whose stop 5 selects a path its pixel does not have fails when checked, naming stop 5", "[tour]") {
    std::string text = "{\"stops\": [";
    for (int k = 1; k <= 6; ++k)
        text += std::string(k > 1 ? "," : "") + "\n {\"title\": \"S" + std::to_string(k) +
                "\", \"caption\": \"c.\", \"scene\": \"pair\", \"width\": 32, \"height\": 32, \"select\": \"16,16" +
                (k == 5 ? ":eye/refraction" : "") + "\"}";
    text += "]}";
    const rc::Tour t = rc::parseTour(text, "five.json");
    try {
        rc::checkTour(t);
        FAIL("stop 5 was accepted");
    } catch (const rc::TourError& e) {
        INFO(e.what());
        REQUIRE(std::string(e.what()).rfind("five.json:6:", 0) == 0);
        REQUIRE(std::string(e.what()).find("stop 5 (S5): select: ") != std::string::npos);
    }
}

TEST_CASE("a stop's claims are read, parsed and checked against what the stop draws", "[tour][claims]") {
    const rc::Tour t = rc::parseTour(R"({"stops": [
  {"title": "A", "caption": "c.", "scene": "pair", "compare": "none:scanline", "overlays": ["misses"],
   "claims": ["right.misses < 0.5*left.misses", "reason == flushed"]},
  {"title": "B", "caption": "c.", "scene": "pair", "claims": "blockers >= 1"}]})",
                                     "t.json");
    REQUIRE(t.stops[0].claims.size() == 2);
    REQUIRE(t.stops[0].claimsLine == 3);
    REQUIRE(t.stops[1].claims == std::vector<std::string>{"blockers >= 1"});
    std::vector<rc::Claim> claims;
    REQUIRE(rc::parseStopClaims(t.stops[0], claims).empty());
    REQUIRE(claims[0].lhs.pane == "right");
    REQUIRE(claims[0].rhs.factor == 0.5);
    REQUIRE(claims[0].op == "<");
    REQUIRE(claims[1].rhs.word == "flushed");
    // Stop B lists blockers but does not draw the hull
    claims.clear();
    REQUIRE(rc::parseStopClaims(t.stops[1], claims).find("the cone overlay draws") != std::string::npos);
    std::string error;
    REQUIRE_FALSE(rc::parseClaim("misses", error));
    REQUIRE(error.find("compares two sides") != std::string::npos);
    REQUIRE_FALSE(rc::parseClaim("left.mises < 3", error));
    REQUIRE(error.find("unknown quantity 'mises'") != std::string::npos);
    REQUIRE_FALSE(rc::parseClaim("tests > flushed", error));
    REQUIRE(error.find("only with == or !=") != std::string::npos);
    REQUIRE_FALSE(rc::parseClaim("1 < 2", error));
    // A right pane only where the stop compares
    const auto c = rc::parseClaim("right.tests > 0", error);
    REQUIRE(c);
    REQUIRE(rc::claimNotDrawn(*c, false, {}, "", {}).find("without 'compare'") != std::string::npos);
    REQUIRE(rc::claimNotDrawn(*c, true, {}, "", {}).empty());
}

TEST_CASE("claims read from a render hold or fail as the render is", "[tour][claims]") {
    rc::RenderOptions ro;
    ro.cache = rc::CacheKind::Blocker;
    ro.width = ro.height = 48;
    rc::SessionState s({std::make_shared<const rc::Scene>(rc::loadScene("pair")), ro});
    s.runUntil(rc::RunGoal::ToEnd, 0);
    rc::ClaimView view;
    view.overlays = {"misses"};
    view.panes.push_back({&s, rc::Selection{24 * 48 + 24, -1, -1}});
    std::string error;
    auto check = [&](const std::string& text) {
        const auto c = rc::parseClaim(text, error);
        REQUIRE(c);
        return rc::checkClaim(*c, view);
    };
    REQUIRE(check("objects == 2").holds);
    REQUIRE_FALSE(check("objects == 3").holds);
    REQUIRE(check("path == eye").holds);
    REQUIRE_FALSE(check("path == eye/reflection").holds);
    REQUIRE(check("complete == 1").holds);
    REQUIRE(check("traced_pixels == pixels").holds);
    REQUIRE(check("misses >= 1").holds);
    REQUIRE(check("misses <= all_misses").holds);
    // A right pane the view does not have: the claim fails, saying so
    const rc::ClaimResult r = check("right.misses < misses");
    REQUIRE_FALSE(r.holds);
    REQUIRE(r.reading.find("no such pane") != std::string::npos);
    // Captions: a count no claim states, a pane the stop does not have
    const auto claims = std::vector<rc::Claim>{*rc::parseClaim("objects == 2", error)};
    REQUIRE(rc::captionSlips("Two spheres, \"3 quoted\", Figure 1.", claims, view).empty());
    REQUIRE(rc::captionSlips("Three spheres.", claims, view).size() == 1);
    REQUIRE(rc::captionSlips("Right: none.", claims, view).size() == 1);
}
