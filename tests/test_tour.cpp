// Tours: the JSON a lecture is written in, read with positions for every error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

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
    }
    REQUIRE(files >= 2);
}
