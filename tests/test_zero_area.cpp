// Real input: polygons of zero area (collinear or coincident vertices, as a coarse SPD
// teapot writes) are skipped with a warning at file:line:column and counted in the run's
// left_out; a UTF-8 byte-order mark is accepted. The CLI, the GUI (its statistics panel
// shows leftOut) and the page (its binding reads the same parser) do the same.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "render/left_out.h"
#include "render/render_session.h"
#include "scene/nff_reader.h"

using namespace rc;
namespace fs = std::filesystem;

namespace {

const std::string kData = RAYCACHE_TEST_DATA;
const std::string kScenes = RAYCACHE_SCENES_DIR;
const std::string kTeapot = kData + "/skipped/teapot_zero_area.nff";

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The lines (1-based) that follow a "# zero area" comment: where the file's zero-area
/// polygons start, found without the reader.
std::vector<int> markedLines(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::vector<int> out;
    int n = 0;
    bool marked = false;
    while (std::getline(in, line)) {
        ++n;
        if (marked) out.push_back(n);
        marked = line.rfind("# zero area", 0) == 0;
    }
    return out;
}

std::vector<std::uint8_t> image(const std::shared_ptr<const Scene>& scene, CacheKind cache, OrderKind order,
                                int size) {
    RenderOptions o;
    o.width = o.height = size;
    o.cache = cache;
    o.order = order;
    RenderSession s(scene, o);
    s.run();
    return s.image().rgb8();
}

struct Result {
    int code;
    std::string output;
};

Result runCli(const std::string& args) {
    const fs::path out = fs::temp_directory_path() / ("raycache_zero_area_" + std::to_string(::getpid()) + ".txt");
    const std::string cmd = std::string(RAYCACHE_CLI) + " " + args + " > " + out.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    const std::string text = slurp(out.string());
    fs::remove(out);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a polygon of zero area is skipped and named at file:line:column", "[nff][zero-area]") {
    struct Small {
        const char* file;
        const char* item;
    };
    for (const Small& f : {Small{"polygon_degenerate", "polygon"}, Small{"polygon_collinear_four", "polygon"},
                           Small{"polygon_same_vertex", "polygon"}}) {
        const std::string path = kData + "/skipped/" + f.file + ".nff";
        INFO(path);
        const Scene s = readNffFile(path);
        CHECK(s.objects.empty());
        CHECK(s.skippedCount == 1);
        REQUIRE(s.skipped.size() == 1);
        CHECK(s.skipped[0] == path + ":8:1: " + f.item +
                                  " of zero area skipped (collinear or coincident vertices: no ray can hit it)");
    }
    // A polygon patch is named as one; one that is not planar is still an error
    const std::string view = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 4 4\n";
    const Scene pp = parseNff(view + "pp 3 0 0 0 0 0 1  1 1 0 0 0 1  2 2 0 0 0 1\n", "pp.nff");
    REQUIRE(pp.skipped.size() == 1);
    CHECK(pp.skipped[0].rfind("pp.nff:2:1: polygon patch of zero area skipped", 0) == 0);
    CHECK_THROWS_WITH(parseNff(view + "p 4 0 0 0 1 0 0 1 1 1 0 1 0\n", "bent.nff"),
                      Catch::Contains("bent.nff:2:1: polygon is not planar"));
}

TEST_CASE("a teapot with zero-area triangles renders, each skipped one named, alike with every cache",
          "[nff][zero-area][render]") {
    const std::string text = slurp(kTeapot);
    const std::vector<int> lines = markedLines(text);
    REQUIRE(lines.size() == 8);
    const auto scene = std::make_shared<const Scene>(readNffFile(kTeapot));
    const Scene original = readNffFile(kScenes + "/teapot2.nff");
    // Every real triangle is kept, every zero-area one skipped and named where it starts
    CHECK(scene->size() == original.size());
    CHECK(scene->skippedCount == long(lines.size()));
    REQUIRE(scene->skipped.size() == lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i)
        CHECK(scene->skipped[i].rfind(kTeapot + ":" + std::to_string(lines[i]) + ":1: polygon patch of zero area", 0) == 0);
    // left_out counts them and names each
    const std::vector<std::string> left = leftOut(*scene);
    REQUIRE_FALSE(left.empty());
    CHECK(left[0].rfind("polygons of zero area: 8 skipped", 0) == 0);
    for (int line : lines) CHECK(contains(left[0], kTeapot + ":" + std::to_string(line) + ":1"));
    CHECK(leftOut(original).size() + 1 == left.size());
    // Every cache and order gives the image of the file without them, byte for byte
    const auto reference = image(std::make_shared<const Scene>(original), CacheKind::None, OrderKind::Scanline, 40);
    for (CacheKind cache : allCacheKinds())
        for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
            INFO(toString(cache) << " " << toString(order));
            CHECK(image(scene, cache, order, 40) == reference);
        }
}

TEST_CASE("raycache render warns of each skipped polygon and gives every cache's hash alike", "[cli][zero-area]") {
    const std::vector<int> lines = markedLines(slurp(kTeapot));
    const Result plain = runCli("render " + kScenes + "/teapot2.nff --width 24 --height 24 --hash -q");
    REQUIRE(plain.code == 0);
    for (const char* cache : {"none", "cylinder", "blocker", "blocker+", "blocker+dir"}) {
        const Result r = runCli("render " + kTeapot + " --width 24 --height 24 --hash -q --order bfs --cache " + cache);
        INFO(r.output);
        REQUIRE(r.code == 0);
        for (int line : lines)
            CHECK(contains(r.output, "raycache: warning: " + kTeapot + ":" + std::to_string(line) + ":1: polygon patch of zero area skipped"));
        CHECK(contains(r.output, plain.output));  // the hash line of the file without them
    }
    const Result info = runCli("info " + kTeapot);
    INFO(info.output);
    CHECK(info.code == 0);
    CHECK(contains(info.output, "left out   polygons of zero area: 8 skipped"));
}

TEST_CASE("a UTF-8 byte-order mark is accepted, and columns count from after it", "[nff][bom]") {
    const std::string path = kData + "/good/utf8_bom.nff";
    const std::string text = slurp(path);
    REQUIRE(text.rfind("\xEF\xBB\xBF", 0) == 0);
    const Scene with = readNffFile(path);
    const Scene without = parseNff(text.substr(3), path);
    CHECK(with.size() == 1);
    CHECK(with.spheres.size() == without.spheres.size());
    CHECK(with.camera.width == without.camera.width);
    CHECK(with.name == "utf8_bom");
    // An error on the first line is at the column it has in the page, whose decoder drops the mark
    CHECK_THROWS_WITH(parseNff("\xEF\xBB\xBFz\n", "bom.nff"), Catch::StartsWith("bom.nff:1:1: "));
    CHECK_THROWS_WITH(parseNff("\xEF\xBB\xBF v", "bom.nff"), Catch::StartsWith("bom.nff:1:2: "));
    // A mark anywhere else is still a stray byte
    CHECK_THROWS_WITH(parseNff("v\n\xEF\xBB\xBF", "bom.nff"), Catch::StartsWith("bom.nff:2:1: non-printable byte 0xef"));
    const Result r = runCli("info " + path);
    INFO(r.output);
    CHECK(r.code == 0);
}
