// The raycache command line: stats keys, exit codes, clear errors.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {
struct Result {
    int code;
    std::string output;
};

Result run(const std::string& args) {
    const fs::path out = fs::temp_directory_path() / ("raycache_cli_" + std::to_string(::getpid()) + ".txt");
    const std::string cmd = std::string(RAYCACHE_CLI) + " " + args + " > " + out.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream in(out);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(out);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raycache_cli_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}
}  // namespace

TEST_CASE("render writes a PNG and stats JSON with the documented keys", "[cli]") {
    const fs::path png = scratch("a.png"), json = scratch("a.json");
    const Result r = run("render cube:3 --width 32 --height 24 --cache blocker --order bfs --verify -o " +
                         png.string() + " --stats " + json.string());
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(fs::file_size(png) > 100);
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const char* key : {"scene", "width", "height", "cache", "order", "seconds", "rays", "intersection_tests",
                            "complete_searches", "cylinder_tests", "blocker_lists", "beam_tree",
                            "complete_searches_per_beam", "queue_peak", "regions"})
        REQUIRE(j.contains(key));
    for (const char* key : {"primary", "shadow", "reflection", "refraction", "total"}) REQUIRE(j["rays"].contains(key));
    for (const char* key : {"hits", "misses", "miss_reasons", "verify_disagreements"}) REQUIRE(j["cache"].contains(key));
    for (const char* key : {"cold", "target_missed", "blocker_hit", "left_cylinder", "flushed"})
        REQUIRE(j["cache"]["miss_reasons"].contains(key));
    REQUIRE(j["width"] == 32);
    REQUIRE(j["rays"]["primary"] == 32 * 24);
    REQUIRE(j["cache"]["verify_disagreements"] == 0);
    REQUIRE(j["order"] == "bfs");
    REQUIRE(j["cache"]["strategy"] == "blocker");
}

TEST_CASE("a malformed scene exits 2 naming file and line", "[cli]") {
    const fs::path bad = scratch("bad.nff");
    {
        std::ofstream out(bad);
        out << "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\ns 0 0 0 -1\n";
    }
    const Result r = run("render " + bad.string() + " -o " + scratch("bad.png").string());
    INFO(r.output);
    REQUIRE(r.code == 2);
    REQUIRE(r.output.find(bad.string() + ":8:") != std::string::npos);
    REQUIRE_FALSE(fs::exists(scratch("bad.png")));
}

TEST_CASE("bad flags and values exit 2 with a message", "[cli]") {
    for (const char* args : {"render cube:3 --cache bogus", "render cube:3 --width 0", "render cube:3 --order sideways",
                             "render cube:99999", "render balls:7", "render balls:0", "render", "frobnicate",
                             "render cube:3 --depth x"}) {
        const Result r = run(args);
        INFO(args << "\n" << r.output);
        REQUIRE(r.code == 2);
        REQUIRE_FALSE(r.output.empty());
    }
}

TEST_CASE("scenes and info describe the built-ins", "[cli]") {
    const Result scenes = run("scenes");
    REQUIRE(scenes.code == 0);
    REQUIRE(scenes.output.find("cube:N") != std::string::npos);
    REQUIRE(scenes.output.find("balls:N") != std::string::npos);
    const Result info = run("info cube:3");
    REQUIRE(info.code == 0);
    REQUIRE(info.output.find("spheres    27") != std::string::npos);
    REQUIRE(info.output.find("shadow") != std::string::npos);
}

TEST_CASE("bench measures every search, cache and order side by side", "[cli][bench]") {
    const fs::path csv = scratch("bench.csv");
    const Result r = run("bench --scenes cube:4 --width 24 --repeat 1 --csv " + csv.string());
    INFO(r.output);
    REQUIRE(r.code == 0);
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    REQUIRE(line.rfind("scene,accel,cache,order,threads,seconds,rays,rays_per_second,tests_per_ray", 0) == 0);
    // tests per ray of each configuration, by "accel/cache/order"
    std::map<std::string, double> perRay;
    std::map<std::string, double> rays;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream fields(line);
        for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
        REQUIRE(f.size() == 12);
        // Every RayCache render's image is the uncached one's (a replay keeps none: -1)
        if (f[1] == "table") REQUIRE(f[11] == "-1");
        else if (f[1] != "embree") REQUIRE(f[11] == "1");
        perRay[f[1] + "/" + f[2] + "/" + f[3]] = std::stod(f[8]);
        rays[f[1] + "/" + f[2] + "/" + f[3]] = std::stod(f[6]);
    }
    for (const char* accel : {"linear", "grid", "bvh"}) {
        REQUIRE(perRay.count(std::string(accel) + "/none/scanline"));
        for (const char* cache : {"cylinder", "blocker"})
            for (const char* order : {"scanline", "bfs"})
                REQUIRE(perRay.count(std::string(accel) + "/" + cache + "/" + order));
    }
    // Every configuration traces the same rays; a hierarchy tests fewer objects than the scan
    for (const auto& [config, n] : rays)
        if (config.rfind("embree", 0) != 0) REQUIRE(n == rays["linear/none/scanline"]);
    REQUIRE(perRay["bvh/none/scanline"] < perRay["linear/none/scanline"] / 4);
    // What a render costs besides searching: both orders answered from a table, no test made
    for (const char* order : {"scanline", "bfs"}) REQUIRE(perRay.at(std::string("table/none/") + order) == 0.0);
    REQUIRE(r.output.find("ns per object test") != std::string::npos);
    REQUIRE(perRay["linear/blocker/bfs"] < perRay["linear/none/scanline"]);
}

TEST_CASE("render --hash prints the SHA-256 of the pixel bytes, rows top to bottom, as sha256sum does", "[cli]") {
    const fs::path ppm = scratch("h.ppm"), raw = scratch("h.rgb");
    const Result r = run("render cube:3 --width 32 --height 24 --cache blocker --order bfs -q --hash -o " + ppm.string());
    INFO(r.output);
    REQUIRE(r.code == 0);
    REQUIRE(r.output.size() == 65);  // 64 hex digits and a newline, nothing else under -q
    // The PPM's pixel bytes, without its header, hashed by coreutils
    std::ifstream in(ppm, std::ios::binary);
    std::string magic;
    int w = 0, h = 0, maxval = 0;
    in >> magic >> w >> h >> maxval;
    in.get();
    REQUIRE(magic == "P6");
    REQUIRE(w == 32);
    REQUIRE(h == 24);
    std::vector<char> pixels(std::size_t(w) * h * 3);
    in.read(pixels.data(), std::streamsize(pixels.size()));
    REQUIRE(in.gcount() == std::streamsize(pixels.size()));
    REQUIRE(in.peek() == EOF);
    std::ofstream(raw, std::ios::binary).write(pixels.data(), std::streamsize(pixels.size()));
    const std::string cmd = "sha256sum " + raw.string() + " > " + raw.string() + ".sum";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream sum(raw.string() + ".sum");
    std::string digest;
    sum >> digest;
    REQUIRE(r.output.substr(0, 64) == digest);

    // Every cache and order gives the same image, so the same hash; another scene another
    for (const char* other : {"--cache none --order scanline", "--cache blocker+dir --order progressive"})
        REQUIRE(run(std::string("render cube:3 --width 32 --height 24 -q --hash ") + other).output == r.output);
    REQUIRE(run("render cube:4 --width 32 --height 24 -q --hash").output != r.output);
}
