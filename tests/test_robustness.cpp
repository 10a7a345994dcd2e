// Robustness: bad input never crashes, hangs or leaves a partial file.
//  - the CLI on every malformed scene (tests/data/malformed, tests/data/robustness/bad):
//    exit 2 and the reader's `file:line:column: message`, for `render` and `info`;
//  - more malformed cases, each at its exact line and column;
//  - extreme but valid scenes (tests/data/robustness/extreme) rendered with every cache,
//    order and complete search, every pixel finite;
//  - limits and bad values on the command line: exit 2 before any work;
//  - unwritable outputs and interrupted renders: a clear error and never a partial file;
//  - every input the fuzzers ever broke (tests/data/regressions) parses or fails cleanly
//    and renders as fuzz/fuzz_render renders it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "render/render_session.h"
#include "scene/nff_reader.h"

namespace fs = std::filesystem;
using namespace rc;

namespace {

const std::string kData = RAYCACHE_TEST_DATA;
const std::string kCli = RAYCACHE_CLI;

/// A folder of this test process's own, emptied on first use.
fs::path scratch(const std::string& name = "") {
    static const fs::path dir = [] {
        const fs::path d = fs::temp_directory_path() / ("raycache_robustness_" + std::to_string(::getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        return d;
    }();
    return name.empty() ? dir : dir / name;
}

struct Result {
    int code;  ///< exit code, or -signal when killed by one
    std::string output;
};

/// Runs the CLI with `args` (no shell: arguments are passed as they are), stdout and
/// stderr captured together; `addressSpace` bytes (0: no limit) as with `ulimit -v`.
Result runCli(const std::vector<std::string>& args, rlim_t addressSpace = 0) {
    static int counter = 0;
    const fs::path out = scratch("output_" + std::to_string(++counter) + ".txt");
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        if (addressSpace > 0) {
            const rlimit limit{addressSpace, addressSpace};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        std::vector<char*> argv{const_cast<char*>(kCli.c_str())};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(kCli.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    std::ifstream in(out);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(out);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status), ss.str()};
}

std::vector<fs::path> nffFiles(const std::string& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".nff") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// The reader's error for a file that must be malformed.
std::string readerError(const fs::path& path) {
    try {
        readNffFile(path.string());
    } catch (const SceneError& e) {
        return e.what();
    }
    FAIL("no SceneError for " << path);
    return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// A whole PNG: the signature at the start and the IEND chunk at the very end.
bool completePng(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string signature = "\x89PNG\r\n\x1a\n";
    const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    return bytes.size() > signature.size() + iend.size() && bytes.compare(0, signature.size(), signature) == 0 &&
           bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
}

/// Files that atomic writes leave behind when they go wrong: `name.tmp.PID`.
std::vector<std::string> temporaryFiles(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(dir))
        if (contains(e.path().filename().string(), ".tmp.")) found.push_back(e.path().string());
    return found;
}

/// Renders `scene` at a tiny size with every cache, order and complete search; every
/// pixel must be finite. Returns how many renders ran: 3 caches x 3 orders x 3 searches.
/// Renders `scene` with every cache, order and search; each image must equal the uncached
/// scanline linear-scan image byte for byte (the exactness promise), with no --verify
/// disagreement, one eye ray per pixel and finite sums.
void renderEveryWay(const std::shared_ptr<const Scene>& scene, int size, int depth) {
    std::vector<std::uint8_t> reference;
    for (CacheKind cache : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker})
        for (OrderKind order : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst})
            for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
                RenderOptions o;
                o.width = size;
                o.height = size;
                o.cache = cache;
                o.order = order;
                o.accel = accel;
                o.shading.maxDepth = depth;
                o.band = 2;
                o.verify = cache != CacheKind::None;
                RenderSession session(scene, o);
                INFO("cache " << int(cache) << " order " << int(order) << " accel " << int(accel));
                REQUIRE(session.run());
                CHECK(session.counters().rays[int(RayKind::Primary)] == std::uint64_t(size * size));
                CHECK(session.counters().verifyDisagreements == 0);
                for (int p = 0; p < size * size; ++p) {
                    const Vec3 v = session.image().value(p);
                    REQUIRE((std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)));
                }
                if (reference.empty()) reference = session.image().rgb8();
                CHECK(session.image().rgb8() == reference);
            }
}

struct Bad {
    const char* file;
    int line;
    int column;
    const char* message;
};

// More malformed input, beside tests/data/malformed (whose table is in test_nff_reader.cpp)
// clang-format off
const Bad kBad[] = {
    {"pp_huge_count",               8,  4, "polygon patch vertex count '4000000000' exceeds the limit of 10000"},
    {"polygon_count_zero",          8,  3, "a polygon needs at least 3 vertices, found '0'"},
    {"polygon_count_1e300",         8,  3, "number out of range for polygon vertex count: '1e300'"},
    {"pp_two_vertices",             8,  4, "a polygon patch needs at least 3 vertices, found '2'"},
    {"polygon_keyword_only",        8,  2, "expected a number for polygon vertex count, found end of file"},
    {"sphere_nan_radius",           8,  9, "NaN or infinity is not allowed (sphere radius is 'nan')"},
    {"sphere_inf_centre",           8,  3, "NaN or infinity is not allowed (sphere centre x is 'inf')"},
    {"sphere_negative_zero_radius", 8,  9, "sphere radius must be positive, found '-0'"},
    {"sphere_huge_coordinate",      8,  3, "number out of range for sphere centre x: '1e101'"},
    {"sphere_underflow_radius",     8,  9, "number out of range for sphere radius: '1e-400'"},
    {"sphere_hex_number",           8,  3, "expected a number for sphere centre x, found '0x10'"},
    {"light_nan_colour",            8, 11, "NaN or infinity is not allowed (light colour green is 'nan')"},
    {"material_inf_shine",          8, 17, "NaN or infinity is not allowed (material Shine is 'inf')"},
    {"view_from_infinite",          2, 10, "NaN or infinity is not allowed (view from z is 'infinity')"},
    {"view_angle_nan",              5,  7, "NaN or infinity is not allowed (view angle is 'NaN')"},
    {"view_truncated",              2,  9, "expected a number for view from z, found end of file"},
    {"view_empty",                  1,  1, "the view ('v') block has no 'from'"},
    {"resolution_negative",         6, 12, "resolution width must be a whole number from 1 to 16384, found '-8'"},
    {"resolution_fractional",       6, 14, "resolution height must be a whole number from 1 to 16384, found '7.5'"},
    {"resolution_absurd",           6, 12, "resolution width must be a whole number from 1 to 16384, found '1e30'"},
    {"only_background",             1, 14, "no view ('v') block"},
    {"nul_only",                    1,  1, "non-printable byte 0x00"},
    {"ctrl_z_at_end",               7, 10, "non-printable byte 0x1a"},
    {"giant_token",                 1, 64, "expected a number for sphere radius, found '9999999999999999999999999999999999999999...'"},
    {"truncated_spd",              72, 30, "expected a number for sphere radius, found end of file"},
};
// clang-format on

}  // namespace

TEST_CASE("more malformed files are reported at file:line:column", "[robustness][nff]") {
    for (const Bad& bad : kBad) {
        const std::string path = kData + "/robustness/bad/" + bad.file + ".nff";
        INFO(path);
        const std::string what = readerError(path);
        INFO(what);
        const std::string prefix = path + ":" + std::to_string(bad.line) + ":" + std::to_string(bad.column) + ": ";
        CHECK(what.rfind(prefix, 0) == 0);
        CHECK(contains(what, bad.message));
    }
    // A file added without an expectation would go untested
    const std::vector<fs::path> files = nffFiles(kData + "/robustness/bad");
    for (const fs::path& f : files) {
        INFO(f);
        CHECK(std::any_of(std::begin(kBad), std::end(kBad), [&](const Bad& b) { return f.stem() == b.file; }));
    }
    CHECK(files.size() == std::size(kBad));
}

TEST_CASE("raycache render and info exit 2 with file:line:column on every malformed file",
          "[robustness][cli]") {
    std::vector<fs::path> files = nffFiles(kData + "/malformed");
    const std::vector<fs::path> more = nffFiles(kData + "/robustness/bad");
    files.insert(files.end(), more.begin(), more.end());
    REQUIRE(files.size() >= 70);
    const fs::path png = scratch("malformed.png");
    for (const fs::path& f : files) {
        const std::string expected = readerError(f);
        INFO(expected);
        // The reader's own message, starting with the path exactly as it was given
        REQUIRE(expected.rfind(f.string() + ":", 0) == 0);
        const Result render = runCli({"render", f.string(), "-q", "-o", png.string(), "--width", "4", "--height", "4"});
        INFO(render.output);
        CHECK(render.code == 2);
        CHECK(contains(render.output, "raycache: " + expected));
        CHECK_FALSE(fs::exists(png));
        const Result info = runCli({"info", f.string()});
        INFO(info.output);
        CHECK(info.code == 2);
        CHECK(contains(info.output, "raycache: " + expected));
    }
    CHECK(temporaryFiles(scratch()).empty());
}

TEST_CASE("extreme but valid scenes render with every cache, order and search", "[robustness][render]") {
    const std::vector<fs::path> files = nffFiles(kData + "/robustness/extreme");
    REQUIRE(files.size() >= 5);
    for (const fs::path& f : files) {
        INFO(f);
        const auto scene = std::make_shared<const Scene>(readNffFile(f.string()));
        renderEveryWay(scene, 6, 4);
    }
    // The largest polygon the reader takes: a circle of 10000 vertices
    std::ostringstream text;
    text.precision(17);
    text << "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8\nl 0 5 5\np "
         << NffLimits::maxPolygonVertices << "\n";
    for (long i = 0; i < NffLimits::maxPolygonVertices; ++i) {
        const double a = 2.0 * std::numbers::pi * double(i) / double(NffLimits::maxPolygonVertices);
        text << std::cos(a) << " " << std::sin(a) << " 0\n";
    }
    const auto circle = std::make_shared<const Scene>(parseNff(text.str(), "circle.nff"));
    REQUIRE(circle->polygons.size() == 1);
    renderEveryWay(circle, 4, 2);
}

TEST_CASE("raycache renders the extreme scenes to complete PNGs", "[robustness][cli]") {
    for (const fs::path& f : nffFiles(kData + "/robustness/extreme")) {
        const fs::path png = scratch(f.stem().string() + ".png");
        const Result r = runCli({"render", f.string(), "-q", "--width", "8", "--height", "8", "--cache", "blocker",
                                 "--order", "bfs", "--verify", "-o", png.string()});
        INFO(f << "\n" << r.output);
        CHECK(r.code == 0);  // 1 would be a --verify disagreement: a broken exactness promise
        CHECK(completePng(png));
    }
}

TEST_CASE("limits and bad values on the command line exit 2 before any work, naming the flag and value",
          "[robustness][cli]") {
    // Each bad command line, and what its message must name: the flag and the value, or
    // the scene as `name:line:column` (0:0 for a name that is not a file's)
    struct Bad {
        std::vector<std::string> args;
        std::vector<std::string> named;
    };
    const std::vector<Bad> bad = {
        {{"render", "cube:2", "--width", "16385"}, {"--width", "16385"}},
        {{"render", "cube:2", "--height", "0"}, {"--height", "0"}},
        {{"render", "cube:2", "--width", "-3"}, {"--width", "-3"}},
        {{"render", "cube:2", "--width", "99999999999999999999"}, {"--width", "99999999999999999999"}},
        {{"render", "cube:2", "--width", "8.5"}, {"--width", "8.5"}},
        {{"render", "cube:2", "--width", ""}, {"--width"}},
        {{"render", "cube:2", "--depth", "0"}, {"--depth", "0"}},
        {{"render", "cube:2", "--depth", "65"}, {"--depth", "65"}},
        {{"render", "cube:2", "--cutoff", "2"}, {"--cutoff", "2"}},
        {{"render", "cube:2", "--cutoff", "-0.5"}, {"--cutoff", "-0.5"}},
        {{"render", "cube:2", "--cutoff", "nan"}, {"--cutoff", "NaN"}},
        {{"render", "cube:2", "--band", "-1"}, {"--band", "-1"}},
        {{"render", "cube:2", "--threads", "257"}, {"--threads", "257"}},
        {{"render", "cube:2", "--threads", "-1"}, {"--threads", "-1"}},
        {{"render", "cube:2", "--seed", "x"}, {"--seed", "x"}},
        {{"render", "cube:2", "--accel", "quantum"}, {"--accel", "quantum"}},
        {{"render", "cube:2", "--cache"}, {"--cache", "missing"}},
        {{"render", "cube:2", "--no-such-flag"}, {"--no-such-flag"}},
        {{"render", "cube:2", "extra-positional"}, {"extra-positional"}},
        {{"render", "cube:0"}, {"raycache: cube:0:0:0: "}},
        {{"render", "cube:65"}, {"raycache: cube:65:0:0: "}},
        {{"render", "cube:-1"}, {"raycache: cube:-1:0:0: "}},
        {{"render", "cube:3x"}, {"raycache: cube:3x:0:0: "}},
        {{"render", "cube"}, {"raycache: cube:0:0: "}},
        {{"render", "no-such-builtin"}, {"raycache: no-such-builtin:0:0: "}},
        {{"render", "/no/such/file.nff"}, {"raycache: /no/such/file.nff:0:0: "}},
        {{"render", kData}, {"raycache: " + kData + ":0:0: "}},
        {{"info"}, {"scene"}},
        {{"info", "cube:0"}, {"raycache: cube:0:0:0: "}},
        {{"info", "/no/such/file.nff"}, {"raycache: /no/such/file.nff:0:0: "}},
        {{"table1", "--sizes", "0"}, {"--sizes", "0"}},
        {{"table1", "--sizes", "65"}, {"--sizes", "65"}},
        {{"table1", "--repeat", "0"}, {"--repeat", "0"}},
        {{"table1", "--sizes", "3,x"}, {"--sizes", "x"}},
        {{}, {"subcommand"}},
    };
    const fs::path png = scratch("rejected.png");
    for (const Bad& b : bad) {
        std::vector<std::string> args = b.args;
        // A render that started would write this file
        if (!args.empty() && args[0] == "render") args.insert(args.begin() + 1, {"-q", "-o", png.string()});
        std::string shown;
        for (const std::string& a : args) shown += "'" + a + "' ";
        const Result r = runCli(args);
        INFO(shown << "\n" << r.output);
        CHECK(r.code == 2);
        for (const std::string& part : b.named) CHECK(contains(r.output, part));
        CHECK_FALSE(fs::exists(png));  // rejected up front, not after a render
    }
}

TEST_CASE("a malformed scene exits 2 with file:line:column through every subcommand", "[robustness][cli]") {
    const fs::path dir = scratch("bad_suite");
    fs::create_directories(dir);
    for (const char* name : {"angle_zero.nff", "duplicate_from.nff"}) {
        const fs::path f = fs::path(kData) / "malformed" / name;
        const std::string expected = "raycache: " + readerError(f);
        // The stiff suite reads every file of its folder: a good one and this one
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy_file(f, dir / name);
        fs::copy_file(fs::path(kData) / ".." / "stiff" / "tangent.nff", dir / "tangent.nff");
        const std::string bad = f.string();
        const std::vector<std::vector<std::string>> commands = {
            {"render", bad, "-q", "--width", "4", "--height", "4"},
            {"info", bad},
            {"table1", "--scenes", bad, "--repeat", "1", "--width", "4", "--height", "4"},
            {"bench", "--scenes", bad, "--repeat", "1", "--width", "4", "--height", "4"},
            {"convergence", bad, "--width", "4", "--height", "4"},
            {"coherence", bad, "--sweep", "spp", "--width", "4", "--height", "4", "--repeat", "1"},
            {"stability", "--suite", dir.string()},
        };
        for (const auto& args : commands) {
            const Result r = runCli(args);
            INFO(args[0] << " " << name << "\n" << r.output);
            CHECK(r.code == 2);
            // The suite names the file where it found it
            CHECK(contains(r.output, args[0] == "stability" ? "raycache: " + readerError(dir / name) : expected));
        }
    }
    fs::remove_all(dir);
}

TEST_CASE("an unwritable output exits 2 with a clear error and leaves no file", "[robustness][cli]") {
    const fs::path dir = scratch("unwritable");
    fs::create_directories(dir / "a_directory");
    const std::vector<std::pair<std::string, std::string>> outputs = {
        {"-o", (dir / "no_such_dir" / "x.png").string()},
        {"--stats", (dir / "no_such_dir" / "x.json").string()},
        {"-o", (dir / "a_directory").string()},
        {"--stats", (dir / "a_directory").string()},
        {"-o", ""},
    };
    for (const auto& [flag, path] : outputs) {
        const Result r = runCli({"render", "cube:2", "-q", "--width", "8", "--height", "8", flag, path});
        INFO(flag << " " << path << "\n" << r.output);
        CHECK(r.code == 2);
        CHECK(contains(r.output, path));
        CHECK_FALSE(fs::exists(dir / "no_such_dir"));
        CHECK(fs::is_directory(dir / "a_directory"));
        CHECK(fs::is_empty(dir / "a_directory"));
        CHECK(temporaryFiles(dir).empty());
    }
    // A device that refuses the write (every write to /dev/full fails): written in place,
    // never renamed over, and the failure found when the files are written is exit 2 too
    if (fs::is_character_file("/dev/full")) {
        for (const char* flag : {"-o", "--stats"}) {
            const Result r = runCli({"render", "cube:2", "-q", "--width", "8", "--height", "8", flag, "/dev/full"});
            INFO(flag << "\n" << r.output);
            CHECK(r.code == 2);
            CHECK(contains(r.output, "raycache: /dev/full: cannot write file"));
            REQUIRE(fs::is_character_file("/dev/full"));
        }
    }
}

/// Whether process `pid` runs raycache and has a handler installed for `sig` (its SigCgt
/// mask in /proc); false once it has gone. Until it has called exec, a forked child is
/// this test, and catches what Catch2 catches.
bool catches(pid_t pid, int sig) {
    const std::string proc = "/proc/" + std::to_string(pid);
    std::error_code ec;
    if (!fs::equivalent(fs::read_symlink(proc + "/exe", ec), kCli, ec)) return false;
    std::ifstream status(proc + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1u;
    return false;
}

TEST_CASE("an interrupted render leaves no partial PNG or JSON", "[robustness][cli]") {
    // The signal is sent when the render has begun: raycache catches SIGINT and SIGTERM
    // from the moment it starts tracing (before that, either would end it as the default
    // action does, before any file is open). No delay decides what is tested
    const fs::path dir = scratch("interrupted");
    fs::create_directories(dir);
    const fs::path png = dir / "out.png", json = dir / "out.json";
    for (int sig : {SIGINT, SIGTERM}) {
        fs::remove(png);
        fs::remove(json);
        const pid_t pid = ::fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1);
            ::dup2(null, 2);
            // Far more rays than the moment between its handler and the signal
            ::execl(kCli.c_str(), kCli.c_str(), "render", "cube:8", "--width", "512", "--height", "512",
                    "--depth", "6", "-q", "-o", png.c_str(), "--stats", json.c_str(), (char*)nullptr);
            ::_exit(127);
        }
        int status = 0;
        bool gone = false;
        while (!catches(pid, sig)) {
            if (::waitpid(pid, &status, WNOHANG) == pid) {
                gone = true;
                break;
            }
            std::this_thread::yield();
        }
        REQUIRE_FALSE(gone);
        ::kill(pid, sig);
        ::waitpid(pid, &status, 0);
        INFO("signal " << sig << ", status " << status);
        // Stopped: 128 + the signal, as a shell reports it, and nothing written
        CHECK(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 128 + sig);
        CHECK_FALSE(fs::exists(png));
        CHECK_FALSE(fs::exists(json));
        CHECK(temporaryFiles(dir).empty());
    }
}

TEST_CASE("inputs the fuzzers found parse or fail cleanly and render", "[robustness][regressions]") {
    // Each file is an input that once crashed, hung or tripped a sanitizer in fuzz/; it
    // must now give a scene or a SceneError, and render as fuzz_render renders it.
    int files = 0;
    for (const fs::path& f : nffFiles(kData + "/regressions")) {
        INFO(f);
        ++files;
        std::shared_ptr<const Scene> scene;
        try {
            scene = std::make_shared<const Scene>(readNffFile(f.string()));
        } catch (const SceneError& e) {
            CHECK(e.line >= 1);
            CHECK(e.column >= 1);
            continue;
        }
        if (scene->size() <= 32 && scene->lights.size() <= 8) renderEveryWay(scene, 4, 2);
    }
    REQUIRE(files >= 1);  // a wrong folder or extension would try none
}

TEST_CASE("running out of memory is exit 2 with a message, not a signal", "[robust][cli][memory]") {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    // The sanitizers reserve terabytes of shadow memory: an address-space limit stops them
    // before main. The release build runs this test.
    SUCCEED("not under a sanitizer");
#else
    // 16384 x 16384 pixels need 6 GiB of sums; the limit is 1 GiB
    const Result r = runCli({"render", "cube:2", "--width", "16384", "--height", "16384", "-q", "-o",
                             scratch("huge.png").string()},
                            rlim_t(1) << 30);
    INFO(r.output);
    REQUIRE(r.code == 2);
    REQUIRE(contains(r.output, "out of memory"));
    REQUIRE_FALSE(fs::exists(scratch("huge.png")));
    // with threads too: the worker's failure reaches the caller
    const Result t = runCli({"render", "cube:2", "--width", "16384", "--height", "4096", "--threads", "2", "-q",
                             "--stats", scratch("huge.json").string(), "-o", scratch("huge.png").string()},
                            rlim_t(1) << 30);
    INFO(t.output);
    REQUIRE(t.code == 2);
    REQUIRE(contains(t.output, "out of memory"));
#endif
}
