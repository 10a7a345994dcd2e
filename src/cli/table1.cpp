/// \file
/// \brief `raycache table1`: the paper's Table 1, measured: every configuration interleaved in
/// one run, so the time ratios hold on a noisy machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <sstream>

#include "analysis/beam_tree.h"
#include "analysis/median.h"
#include "cli/commands.h"
#include "cli/cpu_clock.h"
#include "render/output_files.h"
#include "scene/builtin_scenes.h"
#include "render/answer_replay.h"

namespace rc::cli {

namespace {
struct Config {
    std::string cache;
    std::string order;
};
// No cache, then every registered cache (the paper's two and RayCache's) in scanline and in
// breadth-first order (search/cache_registry.h)
std::vector<Config> configurations() {
    std::vector<Config> out;
    for (const char* order : {"scanline", "bfs"})
        for (const std::string& cache : cacheNames())
            if (std::string(order) == "scanline" || cache != "none") out.push_back({cache, order});
    return out;
}
// Hanrahan 1986, Table 1: "Cached" and "Cached, breadth-first" for N = 3, 4, 5
const std::map<int, std::pair<double, double>> kPaper{{3, {0.53, 0.25}}, {4, {0.29, 0.15}}, {5, {0.20, 0.11}}};

}  // namespace

namespace {
// The size table1 renders at unless told otherwise: the docs' Table 1 page's
constexpr int kTable1Size = 512;

struct Table1Args {
    std::vector<int> sizes{3, 4, 5};
    std::vector<std::string> scenes;  ///< instead of cube:N
    int repeat = 3;
    std::string csv;
    RenderFlags flags;
};

int table1(const Table1Args& a) {
    const std::vector<int>& sizes_ = a.sizes;
    const int repeat_ = a.repeat;
    const std::string& csv_ = a.csv;
    RenderFlags flags = a.flags;
    if (flags.width == 0) flags.width = flags.height == 0 ? kTable1Size : flags.height;
    if (flags.height == 0) flags.height = flags.width;
    // The CSV's header and the table's preamble
    std::ostringstream csv;
    csv << "scene,cache,order,seconds,time_ratio,intersection_tests,tests_ratio,complete_searches,"
           "beam_nodes,searches_per_beam,paper_time_ratio,misses,besides_search_seconds,test_ns,"
           "predicted_time_ratio,own_ns_per_miss,rays,time_over_predicted\n";
    // Every render on one processor (see pinToCurrentCpu())
    const int cpu = pinToCurrentCpu();
    std::printf("Table 1: %s at %dx%d, depth %d, median of %d runs; time and intersection tests\n"
                "relative to no cache, complete searches per beam-tree node, the paper's figure beside.\n",
                a.scenes.empty() ? "cube:N" : "the scenes given", flags.width, flags.height, flags.depth, repeat_);
    if (cpu >= 0) std::printf("Every render ran on processor %d.\n", cpu);
    std::vector<std::string> specs = a.scenes;
    if (specs.empty())
        for (int N : sizes_) specs.push_back("cube:" + std::to_string(N));
    for (const std::string& spec : specs) {
        // Render every configuration, interleaved, timed on one processor
        auto scene = std::make_shared<const Scene>(loadScene(spec, flags.seed));
        const int N = spec.rfind("cube:", 0) == 0 ? std::atoi(spec.c_str() + 5) : 0;
        const std::vector<Config> kConfigs = configurations();
        const int configs = int(kConfigs.size());
        std::vector<std::vector<double>> times(configs);
        std::vector<Counters> counts(configs);
        BeamTreeStats beams;
        // What a render costs besides searching, in each order: the uncached render's
        // answers, recorded once, then replayed from the table (timed with the others).
        // Breadth-first order in the band the paper's cache works in
        std::vector<AnswerTable> tables(2);
        std::vector<std::vector<double>> replayTimes(2);
        const int band = flags.band;
        auto replayed = [&](int k) {
            flags.cache = "none";
            flags.order = k == 0 ? "scanline" : "bfs";
            RenderOptions o = flags.options();
            if (band == kAutoBand) o.band = bandFor(o.accel, CacheKind::Blocker);
            return o;
        };
        // The beam tree from the uncached render that records the answers: a render that
        // feeds a sink is slower, so no timed render does
        {
            BeamTreeBuilder builder(flags.width, flags.height);
            for (int k = 0; k < 2; ++k) tables[k] = recordAnswers(scene, replayed(k), k == 0 ? &builder : nullptr);
            beams = builder.build();
        }
        for (int r = 0; r < repeat_; ++r) {
            for (int k = 0; k < 2; ++k) {
                RenderSession session(scene, replayed(k), std::make_unique<TableSearch>(*scene, tables[k]));
                const double start = threadSeconds();
                session.run();
                replayTimes[k].push_back(threadSeconds() - start);
            }
            for (int c = 0; c < configs; ++c) {
                flags.cache = kConfigs[c].cache;
                flags.order = kConfigs[c].order;
                RenderSession session(scene, flags.options());
                const double start = threadSeconds();
                session.run();
                times[c].push_back(threadSeconds() - start);
                counts[c] = session.counters();
            }
        }
        // The table: each configuration against no cache, the paper's figure beside
        const double t0 = median(times[0]);
        const double tests0 = double(counts[0].intersectionTests);
        // [cost-model]
        // An object test: the uncached render less what it costs besides searching, per test.
        // The counts then predict each configuration's time as if the cache's own work
        // (lookups, building lists and cylinders, the order's bookkeeping beyond the
        // replay) were free; the rest, per miss, is that work.
        const double besides[2] = {median(replayTimes[0]), median(replayTimes[1])};
        const double testSeconds = (t0 - besides[0]) / tests0;
        // [cost-model]
        std::printf("\n%s: costs measured in this run: an object test %.2f ns; a ray besides searching "
                    "%.0f ns (scanline), %.0f ns (bfs)\n",
                    scene->name.c_str(), 1e9 * testSeconds, 1e9 * besides[0] / double(counts[0].totalRays()),
                    1e9 * besides[1] / double(counts[0].totalRays()));
        std::printf("%s: %d objects; beam tree %lld nodes, %.2f rays per pixel, coherence %.2e\n",
                    scene->name.c_str(), scene->size(), (long long)beams.nodes, beams.averageRayTreeSize, beams.coherence);
        std::printf("  %-23s %8s %7s %8s %10s %13s %10s %10s %12s\n", "configuration", "seconds", "time", "paper",
                    "tests", "searches/beam", "predicted", "time/pred", "ns/miss own");
        std::vector<double> medians(configs), ownSeconds(configs);
        for (int c = 0; c < configs; ++c) {
            const double t = median(times[c]);
            const double perBeam = beams.nodes ? double(counts[c].completeSearches) / double(beams.nodes) : 0.0;
            std::string paper = "-";
            auto it = kPaper.find(N);
            if (c == 0) paper = "1.00";
            else if (it != kPaper.end() && kConfigs[c].cache == "blocker")
                paper = std::to_string(kConfigs[c].order == "bfs" ? it->second.second : it->second.first).substr(0, 4);
            const std::string name = kConfigs[c].cache + ", " + kConfigs[c].order;
            const double base = besides[kConfigs[c].order == "bfs" ? 1 : 0];
            const double predicted = (base + testSeconds * double(counts[c].intersectionTests)) / t0;
            const double misses = double(counts[c].misses);
            const double ownPerMiss = misses > 0.0 ? 1e9 * (t - predicted * t0) / misses : 0.0;
            // What the cache's own work adds to its tests: 1 if it were free
            const double overPredicted = t / (predicted * t0);
            medians[c] = t;
            ownSeconds[c] = ownPerMiss * 1e-9;
            std::printf("  %-23s %8.3f %7.3f %8s %10.3f %13.2f %10.3f %10.2f %12.0f\n", name.c_str(), t, t / t0,
                        paper.c_str(), double(counts[c].intersectionTests) / tests0, perBeam, predicted, overPredicted,
                        ownPerMiss);
            csv << scene->name << ',' << kConfigs[c].cache << ',' << kConfigs[c].order << ',' << t << ',' << t / t0 << ','
                << counts[c].intersectionTests << ',' << double(counts[c].intersectionTests) / tests0 << ','
                << counts[c].completeSearches << ',' << beams.nodes << ',' << perBeam << ',' << paper << ','
                << counts[c].misses << ',' << base << ',' << 1e9 * testSeconds << ',' << predicted << ','
                << ownPerMiss << ',' << counts[c].totalRays() << ',' << overPredicted << '\n';
        }
        // Breadth-first against scanline with the same cache, side by side in this run
        auto bfsAgainstScanline = [&](const char* title, auto ratio) {
            std::printf("  %s", title);
            for (int c = 0; c < configs; ++c) {
                if (kConfigs[c].order != "bfs") continue;
                for (int s = 0; s < configs; ++s)
                    if (kConfigs[s].order == "scanline" && kConfigs[s].cache == kConfigs[c].cache)
                        std::printf(" %s %.2f", kConfigs[c].cache.c_str(), ratio(c, s));
            }
            std::printf("\n");
        };
        bfsAgainstScanline("bfs / scanline time, same cache:", [&](int c, int s) { return medians[c] / medians[s]; });
        // [bfs-bound]
        // What breadth-first would reach if its order cost a ray no more than scanline order
        // and a miss no more than scanline's: scanline's time less the tests and misses it saves
        bfsAgainstScanline("bfs / scanline if the fill were free:", [&](int c, int s) {
            const double tests = double(counts[s].intersectionTests) - double(counts[c].intersectionTests);
            const double misses = double(counts[s].misses) - double(counts[c].misses);
            return (medians[s] - testSeconds * tests - ownSeconds[s] * misses) / medians[s];
        });
        // [bfs-bound]
    }
    if (!csv_.empty()) writeTextFile(csv_, csv.str());
    return 0;
}

}  // namespace

void addTable1Command(CLI::App& app, Commands& out) {
    auto a = std::make_shared<Table1Args>();
    CLI::App* c = app.add_subcommand("table1", "reproduce the paper's Table 1 on cube:N");
    c->add_option("--sizes", a->sizes, "values of N, e.g. 3,4,5")->delimiter(',')
        ->check(CLI::Range(1, 64))->capture_default_str();
    c->add_option("--repeat", a->repeat, "repeats; times are medians")->check(CLI::Range(1, 100))
        ->capture_default_str();
    c->add_option("--scenes", a->scenes, "other scenes instead of cube:N (e.g. scenes/balls2.nff)")
        ->delimiter(',');
    c->add_option("--csv", a->csv, "also write the table as CSV")->check(outputFile());
    a->flags.addTo(c, false);
    // Every scene renders at one size here, not the scene's own
    c->get_option("--width")->description("image width (default: " + std::to_string(kTable1Size) +
                                          ", or --height; every scene, cube:N or not)");
    c->get_option("--height")->description("image height (default: the width)");
    out.push_back({c, [a] { return table1(*a); }});
}

}  // namespace rc::cli
