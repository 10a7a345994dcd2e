// The toy cache of toy_cache.cpp, added as docs/pages/adding_a_cache.md says, is in the
// registry, renders the uncached image, and shows in the CLI's choices, `raycache list` and
// `table1` of a raycache built with it (raycache_with_toy_cache).
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "render/left_out.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/cache_registry.h"

using namespace rc;
namespace fs = std::filesystem;

namespace {

struct Result {
    int code;
    std::string output;
};

Result run(const std::string& cli, const std::string& args) {
    const fs::path out = fs::temp_directory_path() / ("raycache_toy_" + std::to_string(::getpid()) + ".txt");
    const std::string cmd = cli + " " + args + " > " + out.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream in(out);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(out);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the toy cache is registered after the built-in ones and renders the uncached image", "[registry]") {
    const auto toy = parseCacheKind("toy");
    REQUIRE(toy);
    CHECK(toString(*toy) == "toy");
    CHECK(int(*toy) >= int(CacheKind::BlockerDirections) + 1);
    CHECK(allCacheKinds().back() == *toy);
    auto scene = std::make_shared<const Scene>(loadScene("cube:2", 1986));
    for (OrderKind order : allOrderKinds()) {
        INFO(toString(order));
        RenderOptions o;
        o.width = o.height = 24;
        o.order = order;
        RenderSession none(scene, o);
        none.run();
        o.cache = *toy;
        RenderSession withToy(scene, o);
        withToy.run();
        CHECK(withToy.image().rgb8() == none.image().rgb8());
        CHECK(withToy.strategy().kind() == *toy);
        CHECK(withToy.counters().misses == withToy.counters().completeSearches);
        CHECK(withToy.counters().hits == 0);
    }
    // A name is registered once
    CHECK_THROWS_AS(registerCache({"toy", "again", cacheRegistry()[0].make}), std::logic_error);
}

TEST_CASE("a raycache built with the toy cache offers it everywhere caches are listed", "[registry][cli]") {
    const std::string cli = RAYCACHE_WITH_TOY;
    const Result list = run(cli, "list caches --json");
    INFO(list.output);
    REQUIRE(list.code == 0);
    const nlohmann::json j = nlohmann::json::parse(list.output);
    REQUIRE(j.size() == cacheRegistry().size());
    CHECK(j.back()["name"] == "toy");
    const Result help = run(cli, "render --help");
    CHECK(contains(help.output, "toy (a toy that remembers nothing"));
    const Result none = run(cli, "render cube:2 --width 16 --height 16 --hash -q");
    const Result toy = run(cli, "render cube:2 --width 16 --height 16 --hash -q --cache toy");
    REQUIRE(toy.code == 0);
    CHECK(toy.output == none.output);
    const Result table = run(cli, "table1 --sizes 1 --repeat 1 --width 8");
    INFO(table.output);
    REQUIRE(table.code == 0);
    CHECK(contains(table.output, "toy, scanline"));
    CHECK(contains(table.output, "toy, bfs"));
    // The raycache without it refuses it
    const Result plain = run(RAYCACHE_CLI, "render cube:2 --width 4 --height 4 --cache toy");
    CHECK(plain.code == 2);
}
