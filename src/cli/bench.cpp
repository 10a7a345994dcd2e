/// \file
/// \brief `raycache bench`: rays per second of every complete search, with and without caches,
/// all configurations interleaved in one run so the ratios hold on a noisy machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include "analysis/median.h"
#include "cli/commands.h"
#include "cli/cpu_clock.h"
#include "cli/image_hash.h"
#include "render/output_files.h"
#include "render/parallel_render.h"
#include "scene/builtin_scenes.h"
#include "render/answer_replay.h"
#include "search/embree_search.h"

namespace rc::cli {

namespace {
struct BenchArgs {
    std::vector<std::string> scenes{"cube:5", "cube:10", "cube:20", "scenes/balls2.nff"};
    int repeat = 3;
    int threads = 1;
    int linearLimit = 1000;
    std::string csv;
    RenderFlags flags;
};

struct Config {
    AccelKind accel;
    CacheKind cache;
    OrderKind order;
    bool replay = false;  ///< no search: answers from a table (what a render costs besides)
};

/// One render of `o` answered from `table`, on one thread, as renderParallel would count it.
ParallelRun replay(const std::shared_ptr<const Scene>& scene, const RenderOptions& o, const AnswerTable& table) {
    RenderSession session(scene, o, std::make_unique<TableSearch>(*scene, table));
    session.run();
    ParallelRun run;
    run.counters = session.counters();
    return run;
}

int bench(const BenchArgs& a) {
    // The configurations: every search with no cache and with every cache in both orders
    std::vector<Config> configs;
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
        configs.push_back({accel, CacheKind::None, OrderKind::Scanline});
        for (CacheKind cache : allCacheKinds())  // every registered cache (search/cache_registry.h)
            if (cache != CacheKind::None)
            for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) configs.push_back({accel, cache, order});
    }
    if (embreeAvailable()) configs.push_back({AccelKind::Embree, CacheKind::None, OrderKind::Scanline});
    // What a render costs besides searching: no cache, each order, answers from a table
    for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst})
        configs.push_back({AccelKind::Linear, CacheKind::None, order, true});

    // One thread: every render on one processor (see pinToCurrentCpu())
    const int cpu = a.threads == 1 ? pinToCurrentCpu() : -1;
    if (cpu >= 0) std::printf("Every render ran on processor %d.\n", cpu);
    std::ostringstream csv;
    csv << "scene,accel,cache,order,threads,seconds,rays,rays_per_second,tests_per_ray,speed_vs_embree,ns_per_ray,"
           "same_image\n";
    for (const std::string& spec : a.scenes) {
        // The scene, its size (1024 unless given), the configurations it runs
        auto scene = std::make_shared<const Scene>(loadScene(spec, a.flags.seed));
        RenderOptions base = a.flags.options();
        if (base.width <= 0) base.width = 1024;
        if (base.height <= 0) base.height = base.width;
        std::vector<Config> run;
        for (const Config& c : configs)
            if (c.accel != AccelKind::Linear || c.replay || scene->size() <= a.linearLimit) run.push_back(c);
        // The answers each order asks for, recorded once by an uncached render (untimed)
        std::vector<AnswerTable> tables(2);
        for (const Config& c : run) {
            if (!c.replay) continue;
            RenderOptions o = base;
            o.order = c.order;
            o.accel = scene->size() <= a.linearLimit ? AccelKind::Linear : AccelKind::Bvh;
            tables[c.order == OrderKind::Scanline ? 0 : 1] = recordAnswers(scene, o);
        }
        std::vector<std::vector<double>> times(run.size());
        std::vector<Counters> counts(run.size());
        // Each render's image against the first uncached one's, byte for byte (untimed):
        // 1 the same in every repeat, 0 not, -1 not compared (a replay keeps no image)
        std::vector<int> same(run.size(), -1);
        std::string reference;
        // [bench-interleave]
        for (int r = 0; r < a.repeat; ++r) {
            for (std::size_t c = 0; c < run.size(); ++c) {
                RenderOptions o = base;
                o.accel = run[c].accel;
                o.cache = run[c].cache;
                o.order = run[c].order;
                const double start = processSeconds();
                const ParallelRun result = run[c].replay
                    ? replay(scene, o, tables[run[c].order == OrderKind::Scanline ? 0 : 1])
                    : renderParallel(scene, o, a.threads);
                times[c].push_back(processSeconds() - start);
                counts[c] = result.counters;
                if (run[c].replay) continue;
                const std::string hash = sha256Hex(result.image.rgb8());
                if (reference.empty() && run[c].cache == CacheKind::None && run[c].accel != AccelKind::Embree)
                    reference = hash;
                same[c] = same[c] != 0 && hash == reference ? 1 : 0;
            }
        }
        // [bench-interleave]
        // The table: rays per second, each against Embree's
        double embreeRate = 0.0;
        for (std::size_t c = 0; c < run.size(); ++c)
            if (run[c].accel == AccelKind::Embree) embreeRate = double(counts[c].totalRays()) / median(times[c]);
        std::printf("\n%s: %d objects, %dx%d, %d thread(s), median of %d\n", scene->name.c_str(), scene->size(),
                    base.width, base.height, a.threads, a.repeat);
        std::printf("  %-8s %-11s %-9s %9s %12s %9s %11s %10s %6s\n", "accel", "cache", "order", "seconds", "Mrays/s",
                    "ns/ray", "tests/ray", "vs embree", "image");
        double replayScanline = 0.0;  // seconds of the scanline render answered from a table
        double bestVsEmbree = 0.0;
        std::size_t best = run.size();
        for (std::size_t c = 0; c < run.size(); ++c) {
            const double t = median(times[c]);
            const double rays = double(counts[c].totalRays());
            const double rate = rays / t;
            const double perRay = double(counts[c].intersectionTests) / rays;
            const double vsEmbree = embreeRate > 0.0 ? rate / embreeRate : 0.0;
            const std::string accel = run[c].replay ? "table" : std::string(toString(run[c].accel));
            if (run[c].replay && run[c].order == OrderKind::Scanline) replayScanline = t;
            std::printf("  %-8s %-11s %-9s %9.3f %12.3f %9.1f %11.2f %10.2f %6s\n", accel.c_str(),
                        std::string(toString(run[c].cache)).c_str(), std::string(toString(run[c].order)).c_str(), t,
                        rate / 1e6, 1e9 / rate, perRay, vsEmbree, same[c] < 0 ? "-" : same[c] ? "same" : "DIFFERS");
            csv << scene->name << ',' << accel << ',' << toString(run[c].cache) << ',' << toString(run[c].order) << ','
                << (run[c].replay ? 1 : a.threads) << ',' << t << ',' << rays << ',' << rate << ',' << perRay << ','
                << vsEmbree << ',' << 1e9 / rate << ',' << same[c] << '\n';
            // [bench-best-cache]
            // The fastest cached render whose image is the uncached one's, against Embree
            if (embreeRate > 0.0 && !run[c].replay && run[c].cache != CacheKind::None && same[c] == 1 &&
                vsEmbree > bestVsEmbree) {
                bestVsEmbree = vsEmbree;
                best = c;
            }
            // [bench-best-cache]
        }
        if (best < run.size())
            std::printf("  fastest cache with the uncached image: %s %s %s, %.2fx Embree's rays per second\n",
                        std::string(toString(run[best].accel)).c_str(), std::string(toString(run[best].cache)).c_str(),
                        std::string(toString(run[best].order)).c_str(), bestVsEmbree);
        // [bench-cost-per-test]
        // A sphere test of the uncached scan: its time less what the same render costs
        // besides searching (answered from a table), over its tests
        std::printf("  table: no search, the answers replayed from a table: what a render costs besides searching\n");
        for (std::size_t c = 0; c < run.size(); ++c) {
            if (run[c].replay || run[c].accel != AccelKind::Linear || run[c].cache != CacheKind::None) continue;
            const double tests = double(counts[c].intersectionTests);
            if (a.threads == 1 && replayScanline > 0.0 && tests > 0.0)
                std::printf("  linear scan, no cache: %.2f ns per object test ((%.3f s - %.3f s) / %.0f tests)\n",
                            1e9 * (median(times[c]) - replayScanline) / tests, median(times[c]), replayScanline, tests);
        }
        // [bench-cost-per-test]
        if (scene->size() > a.linearLimit)
            std::printf("  (linear scan left out: more than %d objects; --linear-limit to change)\n", a.linearLimit);
    }
    if (!embreeAvailable()) std::printf("\nEmbree: not in this build (install libembree-dev and rebuild)\n");
    else std::printf("\nEmbree: tests/ray is not counted (its own BVH); it is single precision, for comparison only\n");
    if (!a.csv.empty()) writeTextFile(a.csv, csv.str());
    return 0;
}
}  // namespace

void addBenchCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<BenchArgs>();
    CLI::App* c = app.add_subcommand("bench", "rays per second of every complete search and cache, and Embree");
    c->add_option("--scenes", a->scenes, "scenes to run")->delimiter(',')->capture_default_str();
    c->add_option("--repeat", a->repeat, "repeats; times are medians")->check(CLI::Range(1, 100))->capture_default_str();
    c->add_option("--threads", a->threads, "threads (0: one per core)")->check(CLI::Range(0, 256))->capture_default_str();
    c->add_option("--linear-limit", a->linearLimit, "leave the linear scan out above this many objects")
        ->capture_default_str();
    c->add_option("--csv", a->csv, "also write the table as CSV")->check(outputFile());
    a->flags.addTo(c, false);
    out.push_back({c, [a] { return bench(*a); }});
}

}  // namespace rc::cli
