#include "cli/commands.h"
#include "view/flag_definitions.h"
#include "cli/image_hash.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>

#include "analysis/beam_tree.h"
#include "order/order_registry.h"
#include "geometry/student_code.h"
#include "render/left_out.h"
#include "render/output_files.h"
#include "render/parallel_render.h"
#include "render/report.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"
#include "search/cache_registry.h"
#include "search/search_registry.h"

#include <unistd.h>

namespace rc::cli {

namespace {
// The signal (SIGINT, SIGTERM) that asked a render to stop, 0 when none did
volatile std::sig_atomic_t gStopSignal = 0;
void onStopSignal(int sig) { gStopSignal = sig; }

}  // namespace

void warnSkipped(const Scene& scene) {
    for (const std::string& s : scene.skipped) std::fprintf(stderr, "raycache: warning: %s\n", s.c_str());
    if (scene.skippedCount > long(scene.skipped.size()))
        std::fprintf(stderr, "raycache: warning: %ld more polygons of zero area skipped\n",
                     scene.skippedCount - long(scene.skipped.size()));
}

std::vector<std::string> cacheNames() { return cacheRegistry().names(); }
std::vector<std::string> orderNames() { return orderRegistry().names(); }
std::vector<std::string> searchNames() { return searchRegistry().names(); }

const CLI::Validator& outputFile() {
    static const CLI::Validator v(
        [](std::string& path) -> std::string {
            namespace fs = std::filesystem;
            if (path.empty()) return "the file name is empty";
            std::error_code ec;
            const fs::path p(path);
            if (fs::is_directory(p, ec)) return "'" + path + "' is a directory, not a file";
            const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
            if (!fs::is_directory(dir, ec)) return "cannot write '" + path + "': no folder '" + dir.string() + "'";
            if (::access(dir.c_str(), W_OK) != 0)
                return "cannot write '" + path + "': " + std::strerror(errno);
            return {};
        },
        "FILE", "OutputFile");
    return v;
}

void RenderFlags::addTo(CLI::App* c, bool cacheAndOrder) {
    RenderFlags& f = *this;
    // The options the GUI shares (view/flag_definitions.h)
    if (cacheAndOrder) {
        addCacheOption(c, f.cache)->capture_default_str();
        addOrderOption(c, f.order)->capture_default_str();
    }
    addAccelOption(c, f.accel, false)->capture_default_str();
    addSizeOptions(c, f.width, f.height);
    c->add_option("--depth", f.depth, "maximum ray-tree depth; the eye ray is depth 1")
        ->check(CLI::Range(1, 64))->capture_default_str();
    c->add_option("--cutoff", f.cutoff, "rays whose weight is below this are not spawned (0: off)")
        ->check(CLI::Range(0.0, 1.0))
        ->check(CLI::Validator([](std::string& s) -> std::string {
            // CLI::Range lets NaN through: no comparison with NaN is true
            return std::isnan(std::strtod(s.c_str(), nullptr)) ? "NaN is not a number from 0 to 1" : "";
        }, "", "NotNaN"))
        ->capture_default_str();
    addBandOption(c, f.band);
    c->add_option("--seed", f.seed, "seed of the built-in scenes' jitter and of distributed ray tracing's samples")
        ->capture_default_str();
}

void RenderFlags::addSamplingTo(CLI::App* c, bool spp) {
    // [sampling-flags]
    addSamplingOptions(c, sampling, spp);
    c->add_option("--sample-entries", sampleEntries,
                  "cache entries of samples: per-sample (one per path and sample index) | shared")
        ->check(CLI::IsMember({"per-sample", "shared"}))->capture_default_str();
    // What no single flag can check (glossy rays per pixel grow with the depth): at parse
    // time, so a bad combination stops before the scene is read
    c->callback([this] {
        Sampling s = sampling;
        s.seed = seed;
        if (const auto e = samplingError(s, depth)) throw CLI::ValidationError(*e);
    });
    // [sampling-flags]
}

RenderOptions RenderFlags::options() const {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.cache = *parseCacheKind(cache);
    o.order = *parseOrderKind(order);
    o.accel = *parseAccelKind(accel);
    o.shading.maxDepth = depth;
    o.shading.cutoff = cutoff;
    o.band = band;
    o.verify = verify;
    o.shading.sampling = sampling;
    o.shading.sampling.seed = seed;
    o.sampleEntries = sampleEntries == "shared" ? SampleEntries::Shared : SampleEntries::PerSample;
    return o;
}

namespace {
struct RenderArgs {
    std::string scene, out, stats;
    bool quiet = false, hash = false;
    int threads = 1;
    RenderFlags flags;
};

int renderCommand(const RenderArgs& a) {
    auto scene = std::make_shared<const Scene>(loadScene(a.scene, a.flags.seed));
    warnSkipped(*scene);
    RenderOptions options = a.flags.options();
    if (options.width <= 0) options.width = scene->camera.width;
    if (options.height <= 0) options.height = scene->camera.height;
    if (options.band == kAutoBand) options.band = bandFor(options.accel, options.cache);  // so the statistics name it
    BeamTreeBuilder beams(options.width, options.height);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    bool shown = false;
    double lastShown = 0.0;
    // SIGINT (Ctrl-C) or SIGTERM stops the render and nothing is written; a second one
    // kills at once. One that comes while the files are written waits for them.
    struct sigaction stop {};
    stop.sa_handler = onStopSignal;
    sigemptyset(&stop.sa_mask);
    stop.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &stop, nullptr);
    sigaction(SIGTERM, &stop, nullptr);
    const ParallelRun run = renderParallel(scene, options, a.threads, a.stats.empty() ? nullptr : &beams,
                                           [&](double done) {
        const double s = std::chrono::duration<double>(Clock::now() - start).count();
        if (!a.quiet && s > 1.0 && (s - lastShown > 0.5 || done >= 1.0)) {
            lastShown = s;
            std::fprintf(stderr, "\rrendering %s: %5.1f%%  %6.1f s", scene->name.c_str(), 100.0 * done, s);
            shown = true;
        }
        return gStopSignal == 0;
    });
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (shown) std::fprintf(stderr, "\n");
    if (gStopSignal != 0) {
        std::fprintf(stderr, "raycache: interrupted (%s); no file written\n", strsignal(gStopSignal));
        return 128 + gStopSignal;
    }
    // A student build whose complete search is still tutorial 01's stub has drawn nothing
    if (const std::string notYet = cannotDrawYet(); !notYet.empty()) {
        std::fprintf(stderr, "raycache: %s\n", notYet.c_str());
        return 1;
    }
    // ... and one whose other holes are still stubs says which ran
    if (const std::string stubs = stubsRanNote(); !stubs.empty())
        std::fprintf(stderr, "raycache: %s\n", stubs.c_str());

    if (!a.out.empty() || a.hash) {
        const std::vector<std::uint8_t> rgb = run.image.rgb8();
        if (!a.out.empty()) writeImage(a.out, options.width, options.height, rgb);
        if (a.hash) std::printf("%s\n", sha256Hex(rgb).c_str());
    }
    const Counters& n = run.counters;
    if (!a.stats.empty()) {
        const BeamTreeStats b = beams.build();
        const RenderSummary summary{scene->name, options, n, run.queuePeak, run.regions, run.paths, run.threads,
                                    leftOut(*scene, &options, &n)};
        writeTextFile(a.stats, statsJson(summary, seconds, &b).dump(2) + "\n");
    }
    if (!a.quiet) {
        std::printf("%s %dx%d cache=%s order=%s accel=%s threads=%d: %.3f s, %llu rays, %llu intersection tests, "
                    "%llu complete searches, %llu hits, %llu misses",
                    scene->name.c_str(), options.width, options.height, a.flags.cache.c_str(),
                    a.flags.order.c_str(), a.flags.accel.c_str(), run.threads, seconds,
                    (unsigned long long)n.totalRays(), (unsigned long long)n.intersectionTests,
                    (unsigned long long)n.completeSearches, (unsigned long long)n.hits,
                    (unsigned long long)n.misses);
        if (a.flags.verify) std::printf(", %llu disagreements", (unsigned long long)n.verifyDisagreements);
        std::printf("\n");
        // A first render with no -o: say where the picture did not go
        if (a.out.empty() && !a.hash) std::fprintf(stderr, "raycache: no image written (-o FILE.png writes one)\n");
    }
    return a.flags.verify && n.verifyDisagreements > 0 ? 1 : 0;
}
}  // namespace

void addRenderCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* c = app.add_subcommand("render", "render a scene to PNG and report what it took");
    c->add_option("scene", a->scene, "an .nff file or a built-in such as cube:5 (see `raycache scenes`)")
        ->required();
    c->add_option("-o,--output", a->out, "image file to write: PNG, or binary PPM when it ends in .ppm")
        ->check(outputFile());
    c->add_flag("--hash", a->hash,
                "print the SHA-256 of the image's 8-bit RGB pixel bytes, rows top to bottom (one line, "
                "before the summary; -q leaves only it)");
    c->add_option("--stats", a->stats, "statistics JSON file to write")->check(outputFile());
    c->add_flag("--verify", a->flags.verify, "run the complete search beside every cached answer");
    c->add_flag("-q,--quiet", a->quiet, "no progress line or summary");
    c->add_option("--threads", a->threads, "threads, each with its own cache tree (0: one per core)")
        ->check(CLI::Range(0, 256))->capture_default_str();
    a->flags.addTo(c, true);
    a->flags.addSamplingTo(c, true);
    out.push_back({c, [a] { return renderCommand(*a); }});
}

void addInfoCommand(CLI::App& app, Commands& out) {
    auto scene = std::make_shared<std::string>();
    auto seed = std::make_shared<std::uint64_t>(1986);
    CLI::App* c = app.add_subcommand("info", "what a scene holds and which rays it can produce");
    c->add_option("scene", *scene, "an .nff file or a built-in")->required();
    c->add_option("--seed", *seed, "seed of the built-in scenes' jitter");
    out.push_back({c, [scene, seed] {
    const Scene s = loadScene(*scene, *seed);
    warnSkipped(s);
    int transparent = 0, reflective = 0;
    for (const Object& o : s.objects) {
        transparent += s.materials[o.material].kt > 0.0;
        reflective += s.materials[o.material].ks > 0.0;
    }
    const Vec3 lo = s.bound.c - Vec3(s.bound.r), hi = s.bound.c + Vec3(s.bound.r);
    std::printf("scene      %s\n", s.name.c_str());
    std::printf("spheres    %zu\npolygons   %zu\nlights     %zu\nmaterials  %zu\n", s.spheres.size(),
                s.polygons.size(), s.lights.size(), s.materials.size());
    std::printf("resolution %dx%d\n", s.camera.width, s.camera.height);
    std::printf("bound      centre (%g, %g, %g) radius %g  (box (%g, %g, %g)-(%g, %g, %g))\n", s.bound.c.x,
                s.bound.c.y, s.bound.c.z, s.bound.r, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    std::printf("rays       primary%s%s%s\n", s.lights.empty() ? "" : ", shadow",
                reflective ? ", reflection" : "", transparent ? ", refraction" : "");
    std::printf("objects    %d reflective, %d transparent\n", reflective, transparent);
    const std::vector<std::string> left = leftOut(s);
    std::printf("left out   %s\n", left.empty() ? "nothing" : left.front().c_str());
    for (std::size_t i = 1; i < left.size(); ++i) std::printf("           %s\n", left[i].c_str());
    return 0;
    }});
}

void addScenesCommand(CLI::App& app, Commands& out) {
    CLI::App* c = app.add_subcommand("scenes", "list the built-in scenes");
    out.push_back({c, [] {
        for (const BuiltinInfo& b : builtinScenes())
            std::printf("%-10s %s\n", b.name.c_str(), b.description.c_str());
        return 0;
    }});
}

}  // namespace rc::cli
