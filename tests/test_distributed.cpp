// Distributed ray tracing: pixel samples, spherical lights and glossy reflection keep every
// promise of the caches (identical images for every cache, order, search and thread count),
// leave the classic image alone at their defaults, and refuse bad settings.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <glm/geometric.hpp>

#include "render/parallel_render.h"
#include "scene/builtin_scenes.h"
#include "trace/distributed_sampling.h"

using namespace rc;

namespace {
/// The settings: --spp 4 --light-radius 0.3 --shadow-samples 4 --gloss 5 --gloss-samples 2 --seed 7
Sampling spread() {
    Sampling s;
    s.spp = 4;
    s.lightRadius = 0.3;
    s.shadowSamples = 4;
    s.glossDegrees = 5.0;
    s.glossSamples = 2;
    s.seed = 7;
    return s;
}

RenderOptions small(int size, const Sampling& s) {
    RenderOptions o;
    o.width = o.height = size;
    o.shading.sampling = s;
    return o;
}

ParallelRun render(const std::shared_ptr<const Scene>& scene, RenderOptions o, int threads = 1) {
    return renderParallel(scene, o, threads);
}

int exitCode(const std::string& args) {
    const std::string cmd = std::string(RAYCACHE_CLI) + " " + args + " >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST_CASE("distributed images are identical for every cache, order, search and thread count", "[distributed]") {
    // cube:4 with the settings, at 32x32 so that the 38 renders take a few seconds
    auto scene = std::make_shared<const Scene>(loadScene("cube:4", 1986));
    const RenderOptions base = small(32, spread());
    const ParallelRun reference = render(scene, base);
    const std::vector<std::uint8_t> bytes = reference.image.rgb8();
    // The settings take effect: the image is not the classic one
    REQUIRE(bytes != render(scene, small(32, Sampling{})).image.rgb8());
    for (SampleEntries entries : {SampleEntries::PerSample, SampleEntries::Shared})
        for (CacheKind c : allCacheKinds())
            for (OrderKind o : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst}) {
                RenderOptions opt = base;
                opt.cache = c;
                opt.order = o;
                opt.sampleEntries = entries;
                opt.band = 8;
                opt.verify = c != CacheKind::None;
                const ParallelRun run = render(scene, opt);
                INFO(toString(c) << ", " << toString(o) << (entries == SampleEntries::Shared ? ", shared" : ""));
                REQUIRE(run.counters.verifyDisagreements == 0);
                REQUIRE(run.image.rgb8() == bytes);
                // Not just the bytes: the fixed-point sums themselves
                for (int p = 0; p < 32 * 32; p += 37) REQUIRE(run.image.value(p) == reference.image.value(p));
                REQUIRE(run.counters.totalRays() == reference.counters.totalRays());
            }
    for (AccelKind a : {AccelKind::Grid, AccelKind::Bvh})
        for (int threads : {1, 3}) {
            RenderOptions opt = base;
            opt.cache = CacheKind::BlockerPlus;
            opt.order = OrderKind::BreadthFirst;
            opt.accel = a;
            INFO(int(a) << " on " << threads << " threads");
            REQUIRE(render(scene, opt, threads).image.rgb8() == bytes);
        }
    RenderOptions none3 = base;
    REQUIRE(render(scene, none3, 3).image.rgb8() == bytes);
    // Another seed draws other samples
    RenderOptions other = base;
    other.shading.sampling.seed = 8;
    REQUIRE(render(scene, other).image.rgb8() != bytes);
}

TEST_CASE("with the new options at their defaults the image is the classic one", "[distributed]") {
    // (That the classic image is the one a plain recursive Whitted tracer makes is the
    // instructor's test, tests/instructor/test_whitted_oracles.cpp.)
    for (const std::string spec : {std::string("cube:4"), std::string("glass"),
                                   std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff"}) {
        auto scene = std::make_shared<const Scene>(loadScene(spec, 1986));
        INFO(spec);
        const std::vector<std::uint8_t> plain = render(scene, small(48, Sampling{})).image.rgb8();
        // Sample counts mean nothing without a radius or a gloss angle, and another seed
        // changes nothing when nothing is sampled: still the classic image
        Sampling idle;
        idle.shadowSamples = 8;
        idle.glossSamples = 4;
        idle.seed = 99;
        RenderOptions o = small(48, idle);
        o.cache = CacheKind::BlockerPlus;
        o.order = OrderKind::BreadthFirst;
        REQUIRE(render(scene, o).image.rgb8() == plain);
        // ... and a radius or an angle does change it
        Sampling soft = idle;
        soft.lightRadius = 0.3;
        REQUIRE(render(scene, small(48, soft)).image.rgb8() != plain);
    }
}

TEST_CASE("samples are a pure function of their key and fall where they should", "[distributed]") {
    // Stratified: with 4 samples, sample s lies in its own quarter of the pixel. Drawn in
    // the opposite order, every sample is the same: nothing depends on what came before
    std::vector<glm::dvec2> backwards(50 * 4);
    for (int i = 50 * 4 - 1; i >= 0; --i) backwards[i] = pixelSample(4, i % 4, eyeKey(7, i / 4, i % 4));
    for (int pixel = 0; pixel < 50; ++pixel)
        for (int s = 0; s < 4; ++s) {
            const glm::dvec2 o = pixelSample(4, s, eyeKey(7, pixel, s));
            REQUIRE(o == backwards[pixel * 4 + s]);
            REQUIRE((o.x >= 0.0) == bool(s % 2));
            REQUIRE((o.y >= 0.0) == bool(s / 2));
            REQUIRE(std::abs(o.x) < 0.5);
            REQUIRE(std::abs(o.y) < 0.5);
        }
    // Keys differ by seed, pixel, sample and step
    REQUIRE(eyeKey(7, 3, 0) != eyeKey(8, 3, 0));
    REQUIRE(eyeKey(7, 3, 0) != eyeKey(7, 4, 0));
    REQUIRE(eyeKey(7, 3, 0) != eyeKey(7, 3, 1));
    const std::uint64_t k = eyeKey(7, 3, 0);
    REQUIRE(childKey(k, RayKind::Shadow, 0, 1) != childKey(k, RayKind::Shadow, 1, 0));
    REQUIRE(childKey(k, RayKind::Shadow, 0, 0) != childKey(k, RayKind::Reflection, -1, 0));
    // Light samples lie on the disc through the centre facing p; glossy directions in the cone
    const Light light{Vec3(1.0, 2.0, 3.0), Vec3(1.0), 0.5};
    const Vec3 p(-4.0, 0.5, 1.0);
    const Vec3 axis = glm::normalize(Vec3(0.3, -1.0, 0.2));
    const double alpha = 10.0 * std::numbers::pi / 180.0;
    double farthest = 0.0;
    for (int j = 0; j < 200; ++j) {
        const Vec3 q = lightSample(light, p, childKey(k, RayKind::Shadow, 0, j));
        REQUIRE(glm::length(q - light.position) <= 0.5 * (1.0 + 1e-12));
        REQUIRE(std::abs(glm::dot(q - light.position, glm::normalize(p - light.position))) < 1e-12);
        farthest = std::max(farthest, glm::length(q - light.position));
        const Vec3 d = coneSample(axis, alpha, childKey(k, RayKind::Reflection, -1, j));
        REQUIRE(std::abs(glm::length(d) - 1.0) < 1e-12);
        REQUIRE(glm::dot(d, axis) >= std::cos(alpha) - 1e-12);
    }
    REQUIRE(farthest > 0.4);  // they spread over the disc, not around its centre only
}

TEST_CASE("samples get paths of their own, with entries per sample or shared", "[distributed]") {
    CacheTree per(SampleEntries::PerSample), shared(SampleEntries::Shared);
    for (CacheTree* t : {&per, &shared}) {
        const int eye1 = t->root(1);
        REQUIRE(eye1 != 0);
        REQUIRE(t->root(1) == eye1);
        const int s0 = t->child(0, RayKind::Shadow, 1, 0), s2 = t->child(0, RayKind::Shadow, 1, 2);
        const int deep = t->child(t->child(eye1, RayKind::Reflection, -1, 1), RayKind::Shadow, 0, 3);
        REQUIRE(s0 != s2);
        REQUIRE(t->label(s2) == "eye/shadow 2 #2");
        REQUIRE(t->label(deep) == "eye #1/reflection #1/shadow 1 #3");
        t->entry(s2).state = CacheEntry::State::Loaded;
        t->entry(deep).state = CacheEntry::State::Loaded;
        const bool sharing = t == &shared;
        // Shared: sample 2 uses sample 0's entry, and eye 1's reflection 1's shadow 3 uses
        // eye 0's reflection 0's shadow 0's
        REQUIRE((t->entry(s0).state == CacheEntry::State::Loaded) == sharing);
        const int twin = t->child(t->child(0, RayKind::Reflection, -1, 0), RayKind::Shadow, 0, 0);
        REQUIRE((t->entry(twin).state == CacheEntry::State::Loaded) == sharing);
        REQUIRE((t->entries() < t->size()) == sharing);
    }
}

TEST_CASE("the hull of a shadow ray reaches the light's sphere, not its centre", "[distributed]") {
    // Large lights overlap the spheres: every sampled shadow ray answered from a blocker
    // list must agree with the complete search
    auto scene = std::make_shared<const Scene>(loadScene("cube:3", 1986));
    Sampling s;
    s.lightRadius = 2.0;
    s.shadowSamples = 6;
    for (CacheKind c : {CacheKind::Blocker, CacheKind::BlockerPlus}) {
        RenderOptions o = small(24, s);
        o.cache = c;
        o.verify = true;
        const ParallelRun run = render(scene, o);
        REQUIRE(run.counters.rays[int(RayKind::Shadow)] > 0);
        REQUIRE(run.counters.verifyDisagreements == 0);
    }
}

TEST_CASE("bad sampling settings are refused with exit 2 before any work", "[distributed][cli]") {
    Sampling ok;
    REQUIRE_FALSE(samplingError(ok, 5));
    auto bad = [](auto change, int depth = 5) {
        Sampling s;
        change(s);
        return samplingError(s, depth).has_value();
    };
    REQUIRE(bad([](Sampling& s) { s.spp = 0; }));
    REQUIRE(bad([](Sampling& s) { s.spp = kMaxSpp + 1; }));
    REQUIRE(bad([](Sampling& s) { s.lightRadius = -0.1; }));
    REQUIRE(bad([](Sampling& s) { s.lightRadius = std::nan(""); }));
    REQUIRE(bad([](Sampling& s) { s.lightRadius = INFINITY; }));
    REQUIRE(bad([](Sampling& s) { s.glossDegrees = -1.0; }));
    REQUIRE(bad([](Sampling& s) { s.glossDegrees = std::nan(""); }));
    REQUIRE(bad([](Sampling& s) { s.glossDegrees = 90.5; }));
    REQUIRE(bad([](Sampling& s) { s.shadowSamples = kMaxShadowSamples + 1; }));
    REQUIRE(bad([](Sampling& s) { s.glossSamples = 0; }));
    // Glossy branching: 16 samples at depth 6 is 16^5 = 2^20 rays per pixel (the limit); 7 is over
    auto branching = [](Sampling& s) { s.glossDegrees = 5.0, s.glossSamples = 16; };
    REQUIRE_FALSE(bad(branching, 6));
    REQUIRE(bad(branching, 7));
    // The session refuses them too
    auto scene = std::make_shared<const Scene>(loadScene("cube:2", 1986));
    Sampling neg;
    neg.lightRadius = -1.0;
    REQUIRE_THROWS_AS(RenderSession(scene, small(8, neg)), std::invalid_argument);
    // The command line: exit 2, and no file written
    const std::filesystem::path png =
        std::filesystem::temp_directory_path() / ("raycache_bad_sampling_" + std::to_string(::getpid()) + ".png");
    for (const char* args : {"--spp 0", "--spp 257", "--spp -3", "--light-radius -1", "--light-radius nan",
                             "--light-radius inf", "--gloss -2", "--gloss nan", "--gloss 100",
                             "--shadow-samples 65", "--gloss-samples 17", "--gloss 5 --gloss-samples 16 --depth 8",
                             "--sample-entries some"}) {
        INFO(args);
        REQUIRE(exitCode(std::string("render cube:2 --width 8 --height 8 ") + args + " -o " + png.string()) == 2);
        REQUIRE_FALSE(std::filesystem::exists(png));
    }
    REQUIRE(exitCode("render cube:2 --width 8 --height 8 --spp 2 --light-radius 0.2 --gloss 3 -o " + png.string()) == 0);
    REQUIRE(std::filesystem::exists(png));
    std::filesystem::remove(png);
}

namespace {
/// The rows of a CSV file, each split at commas (the first is the header).
std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}
int column(const std::vector<std::string>& header, const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : int(it - header.begin());
}
}  // namespace

TEST_CASE("coherence sweeps the light radius and the hit rate falls as rays spread", "[distributed][cli]") {
    // The paper: "if rays were randomly chosen ... we would expect few cache hits". Wider
    // lights spread the shadow rays of neighbouring pixels apart
    const std::filesystem::path csv =
        std::filesystem::temp_directory_path() / ("raycache_coherence_" + std::to_string(::getpid()) + ".csv");
    REQUIRE(exitCode("coherence cube:4 --sweep light-radius --width 24 --height 24 --repeat 1 --csv " + csv.string()) == 0);
    const auto rows = readCsv(csv);
    std::filesystem::remove(csv);
    REQUIRE(rows.size() >= 5);  // a header and at least 4 values
    for (const char* name : {"cylinder_scanline_hit_rate", "blocker_scanline_hit_rate", "blocker+_progressive_hit_rate"}) {
        const int c = column(rows[0], name);
        INFO(name);
        REQUIRE(c >= 0);
        REQUIRE(std::stod(rows.back()[std::size_t(c)]) < std::stod(rows[1][std::size_t(c)]));
    }
    // Every configuration traced the same rays: no cache's hit rate is 0, its tests ratio 1
    REQUIRE(std::stod(rows[1][std::size_t(column(rows[0], "none_scanline_hit_rate"))]) == 0.0);
    REQUIRE(std::stod(rows[1][std::size_t(column(rows[0], "none_bfs_tests_ratio"))]) == 1.0);
    // A bad value is refused before any work
    REQUIRE(exitCode("coherence cube:4 --sweep gloss --values 1,120 --width 8 --height 8") == 2);
    REQUIRE(exitCode("coherence cube:4 --sweep spp --values 2.5 --width 8 --height 8") == 2);
    REQUIRE(exitCode("coherence cube:4 --sweep wobble") == 2);
}

TEST_CASE("stochastic convergence: the error falls as the samples grow, the same for every configuration",
          "[distributed][cli]") {
    const std::filesystem::path csv =
        std::filesystem::temp_directory_path() / ("raycache_stochastic_" + std::to_string(::getpid()) + ".csv");
    REQUIRE(exitCode("convergence cube:3 --stochastic --width 24 --height 24 --spp 8 --ref-spp 32 --repeat 1 --csv " +
                     csv.string()) == 0);
    const auto rows = readCsv(csv);
    std::filesystem::remove(csv);
    const int spp = column(rows[0], "spp"), err = column(rows[0], "rmse"), cache = column(rows[0], "cache");
    REQUIRE((spp >= 0 && err >= 0 && cache >= 0));
    // 12 configurations at 1, 2, 4, 8 samples
    REQUIRE(rows.size() == 1 + 12 * 4);
    std::map<int, std::set<std::string>> errors;
    for (std::size_t i = 1; i < rows.size(); ++i) errors[std::stoi(rows[i][std::size_t(spp)])].insert(rows[i][std::size_t(err)]);
    for (const auto& [n, e] : errors) REQUIRE(e.size() == 1);  // identical images, identical errors
    REQUIRE(std::stod(*errors[8].begin()) < std::stod(*errors[1].begin()));
    REQUIRE(exitCode("convergence cube:3 --stochastic --spp 300") == 2);
}
