// Leaving out what a scene does not need: no shadow rays without lights, no reflection
// rays without Ks, no refraction rays without T; `left_out` says so, in the stats JSON
// and in `raycache info`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "render/left_out.h"
#include "render/render_session.h"
#include "render/report.h"
#include "search/blocker_lists.h"
#include "scene/builtin_scenes.h"

using namespace rc;

namespace {
bool has(const std::vector<std::string>& v, const std::string& prefix) {
    return std::any_of(v.begin(), v.end(), [&](const std::string& s) { return s.rfind(prefix, 0) == 0; });
}

Scene twoSpheres(double ks, double kt, bool light) {
    Scene s;
    Material m;
    m.color = Vec3(0.8, 0.5, 0.3);
    m.kd = 0.7;
    m.ks = ks;
    m.shine = 20.0;
    m.kt = kt;
    m.ior = 1.5;
    s.materials.push_back(m);
    s.addSphere({Vec3(-0.8, 0, 0), 0.7}, 0);
    s.addSphere({Vec3(0.8, 0, 0), 0.7}, 0);
    if (light) s.lights.push_back({Vec3(3, 4, 5), Vec3(1.0)});
    s.camera.from = Vec3(0, 0.5, 5);
    s.camera.at = Vec3(0.0);
    s.camera.width = s.camera.height = 24;
    s.finalize();
    return s;
}

Counters render(const Scene& s, CacheKind cache = CacheKind::Blocker) {
    RenderOptions o;
    o.cache = cache;
    RenderSession session(std::make_shared<const Scene>(s), o);
    session.run();
    return session.counters();
}

std::string runCli(const std::string& args) {
    const auto out = std::filesystem::temp_directory_path() / ("raycache_leftout_" + std::to_string(::getpid()));
    const std::string cmd = std::string(RAYCACHE_CLI) + " " + args + " > " + out.string() + " 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(out);
    std::stringstream ss;
    ss << in.rdbuf();
    std::filesystem::remove(out);
    return ss.str();
}
}  // namespace

TEST_CASE("no lights: no shadow rays, and left_out says so", "[left_out]") {
    const Scene s = twoSpheres(0.4, 0.0, false);
    CHECK(render(s).rays[int(RayKind::Shadow)] == 0);
    const auto left = leftOut(s);
    CHECK(has(left, "shadow rays: no lights"));
    CHECK_FALSE(has(left, "reflection rays"));
}

TEST_CASE("no Ks: no reflection rays, no T: no refraction rays", "[left_out]") {
    const Scene dull = twoSpheres(0.0, 0.0, true);
    const Counters n = render(dull);
    CHECK(n.rays[int(RayKind::Reflection)] == 0);
    CHECK(n.rays[int(RayKind::Refraction)] == 0);
    CHECK(n.rays[int(RayKind::Shadow)] > 0);
    const auto left = leftOut(dull);
    CHECK(has(left, "reflection rays: no material has Ks > 0 or T > 0"));
    CHECK(has(left, "refraction rays and interior blocker lists: no transparent objects"));
    CHECK_FALSE(has(left, "shadow rays"));

    // Glass that reflects: nothing of the kind left out, and every kind of ray is traced
    const Scene glass = twoSpheres(0.3, 0.6, true);
    const Counters g = render(glass);
    CHECK(g.rays[int(RayKind::Reflection)] > 0);
    CHECK(g.rays[int(RayKind::Refraction)] > 0);
    CHECK(leftOut(glass).empty());

    // Glass without Ks reflects all the same: a dielectric reflects by Fresnel
    const Scene clear = twoSpheres(0.0, 0.6, true);
    CHECK(render(clear).rays[int(RayKind::Reflection)] > 0);
    CHECK(leftOut(clear).empty());
}

TEST_CASE("depth 1 leaves out every secondary ray but shadows, blocker lists only for pairs met", "[left_out]") {
    const Scene s = twoSpheres(0.3, 0.6, true);
    RenderOptions o;
    o.shading.maxDepth = 1;
    CHECK(has(leftOut(s, &o), "reflection and refraction rays: depth 1"));
    o.shading.maxDepth = 5;
    o.cache = CacheKind::Blocker;
    RenderSession session(std::make_shared<const Scene>(s), o);
    session.run();
    const Counters& n = session.counters();
    const auto left = leftOut(s, &o, &n);
    REQUIRE(has(left, "blocker lists: only for the (origin, target) pairs a ray met"));
    // 2 spheres + the eye as origins, 2 spheres + 1 light as targets: 9 pairs possible.
    // A list is built when a ray of a path hits the object the path's previous ray hit.
    // That is sure to happen for eye rays on either sphere, for rays inside each glass
    // sphere (they can only hit it) and for shadow rays to the light (their target is the
    // light, whatever blocks them). A sphere to the other: only where two reflections in a
    // row cross the gap. The eye to the light: never, no eye ray aims at a light.
    const BlockerLists* lists = session.strategy().blockerLists();
    REQUIRE(lists != nullptr);
    const int eye = lists->eyeSite(), light = lists->lightSite(0);
    std::set<std::pair<int, int>> built;
    for (int origin = 0; origin < lists->sites(); ++origin)
        for (int target = 0; target < lists->sites(); ++target)
            if (lists->find(origin, target)) built.insert({origin, target});
    const std::set<std::pair<int, int>> sure{{eye, 0}, {eye, 1}, {0, 0}, {1, 1}, {0, light}, {1, light}};
    const std::set<std::pair<int, int>> possible{{0, 1}, {1, 0}};
    for (const auto& pair : sure) CHECK(built.count(pair) == 1);
    for (const auto& pair : built) CHECK((sure.count(pair) + possible.count(pair)) == 1);
    CHECK(built.count({eye, light}) == 0);
    CHECK(n.blockerListsBuilt == built.size());
    CHECK(has(left, "blocker lists: only for the (origin, target) pairs a ray met: " + std::to_string(built.size()) +
                        " built, 9 pairs possible"));
}

TEST_CASE("the built-in scenes: cube leaves out refraction, glass nothing", "[left_out]") {
    const auto cube = leftOut(makeBuiltin("cube:2"));
    CHECK(cube == std::vector<std::string>{"refraction rays and interior blocker lists: no transparent objects"});
    CHECK(leftOut(makeBuiltin("glass")).empty());
}

TEST_CASE("stats JSON and raycache info list what was left out", "[left_out][cli]") {
    // A scene of diffuse spheres without lights: no shadows, reflections or refractions
    const auto dir = std::filesystem::temp_directory_path() / ("raycache_leftout_dir_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto nff = dir / "dull.nff";
    std::ofstream(nff) << "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.01\nresolution 8 8\n"
                          "f 1 0 0 1 0 0 0 1\ns 0 0 0 1\n";
    const auto stats = dir / "stats.json";
    runCli("render " + nff.string() + " --cache blocker -q --stats " + stats.string());
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    REQUIRE(j.contains("left_out"));
    const auto left = j["left_out"].get<std::vector<std::string>>();
    CHECK(has(left, "shadow rays: no lights"));
    CHECK(has(left, "reflection rays: no material has Ks > 0 or T > 0"));
    CHECK(has(left, "refraction rays and interior blocker lists: no transparent objects"));
    CHECK(has(left, "blocker lists:"));
    CHECK(j["rays"]["shadow"] == 0);
    const std::string info = runCli("info " + nff.string());
    CHECK(info.find("left out   shadow rays: no lights") != std::string::npos);
    CHECK(info.find("reflection rays: no material has Ks > 0 or T > 0") != std::string::npos);
    std::filesystem::remove_all(dir);
}
