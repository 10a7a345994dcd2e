/// \file
/// \brief `raycache convergence SCENE`: error against run time. For every cache and order, the
/// RMSE of the partial image against the final one as rendering proceeds; and, with
/// jittered supersampling, the RMSE of 1, 2, 4, ... samples per pixel against a
/// high-sample reference, against the time they took. Writes the numbers as CSV and a
/// chart drawn by matplotlib (python3-matplotlib), when it is installed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "study/image_error.h"
#include "render/parallel_render.h"
#include "cli/commands.h"
#include "search/cache_registry.h"
#include "cli/cpu_clock.h"
#include "cli/plot_script.h"
#include "render/output_files.h"
#include "scene/builtin_scenes.h"

namespace rc::cli {

namespace {

struct ConvergenceArgs {
    std::string scene, csv, plot;
    bool stochastic = false;
    int refSpp = 64;
    int spp = 64;
    int refGrid = 12;
    int samples = 100;
    int repeat = 3;
    std::uint64_t jitterSeed = 7;
    RenderFlags flags;
};

// The registered caches that the sweeps take (search/cache_registry.h), read when first
// asked, after every registrar has run
const std::vector<CacheKind>& sweptCaches() {
    static const std::vector<CacheKind> swept = sweptCacheKinds();
    return swept;
}
const OrderKind kOrders[] = {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst};

double at(const std::vector<ProgressPoint>& pts, double fraction) {
    const std::int64_t target = std::int64_t(fraction * double(pts.back().steps));
    for (const ProgressPoint& p : pts)
        if (p.steps >= target) return p.rmse;
    return pts.back().rmse;
}

// The mean RMSE over the render, weighting each sample by the rays (or seconds) it covers:
// the error a viewer sees on average while the image is being made
double meanOver(const std::vector<ProgressPoint>& pts, bool bySeconds) {
    double area = 0.0, span = 0.0;
    for (std::size_t i = 1; i < pts.size(); ++i) {
        const double w = bySeconds ? pts[i].seconds - pts[i - 1].seconds : double(pts[i].steps - pts[i - 1].steps);
        area += w * 0.5 * (pts[i].rmse + pts[i - 1].rmse);
        span += w;
    }
    return span > 0.0 ? area / span : 0.0;
}

// [stochastic-convergence]
// Distributed ray tracing with 1, 2, 4, ... pixel samples: every cache and order renders the
// same image at each count (exactness), so they differ only in the time it takes; the error is
// the RMSE against a reference of many more samples drawn with another seed
int stochastic(const ConvergenceArgs& a) {
    if (a.spp > kMaxSpp) throw std::invalid_argument("--stochastic takes at most " + std::to_string(kMaxSpp) + " --spp");
    // The scene, the image size (64x64 unless given), the sample counts
    auto scene = std::make_shared<const Scene>(loadScene(a.scene, a.flags.seed));
    RenderOptions base = a.flags.options();
    if (base.width <= 0 && base.height <= 0) base.width = base.height = 64;
    if (base.width <= 0) base.width = base.height;
    if (base.height <= 0) base.height = base.width;
    std::vector<int> counts;
    for (int n = 1; n < a.spp; n *= 2) counts.push_back(n);
    counts.push_back(a.spp);
    // The reference: many samples, a seed of its own
    RenderOptions ref = base;
    ref.cache = CacheKind::BlockerPlus;
    ref.shading.sampling.spp = a.refSpp;
    ref.shading.sampling.seed = base.shading.sampling.seed + 1;  // noise of its own
    for (const RenderOptions& o : {base, ref})
        if (const auto e = samplingError(o.shading.sampling, o.shading.maxDepth)) throw std::invalid_argument(*e);
    const double refStart = processSeconds();
    const LinearImage reference = linearImage(renderParallel(scene, ref, 0).image);
    const double refSeconds = processSeconds() - refStart;

    // Render every configuration at every sample count
    const Sampling& sm = base.shading.sampling;
    std::printf("%s at %dx%d, depth %d: distributed ray tracing (light radius %g with %d shadow samples, gloss %g "
                "degrees with %d samples, seed %llu) at 1 to %d samples per pixel, against a reference of %d "
                "samples (seed %llu, %.2f s of CPU). RMSE (values clamped to [0, 1]) and seconds of thread CPU "
                "time, the fastest of %d runs:\n\n",
                scene->name.c_str(), base.width, base.height, base.shading.maxDepth, sm.lightRadius, sm.shadowSamples,
                sm.glossDegrees, sm.glossSamples, (unsigned long long)sm.seed, a.spp, a.refSpp,
                (unsigned long long)ref.shading.sampling.seed, refSeconds, a.repeat);
    std::vector<std::string> names;
    for (CacheKind c : sweptCaches())
        for (OrderKind o : kOrders) names.push_back(std::string(toString(c)) + ", " + std::string(toString(o)));
    std::vector<std::vector<double>> seconds(counts.size(), std::vector<double>(names.size(), 0.0));
    std::vector<double> error(counts.size(), 0.0);
    std::vector<std::uint64_t> rays(counts.size(), 0);
    std::ostringstream csv;
    csv << "kind,cache,order,steps,spp,seconds,rmse\n";
    for (std::size_t i = 0; i < counts.size(); ++i) {
        // The configurations take turns, so that the machine's load falls on all alike
        for (int r = 0; r < a.repeat; ++r)
            for (std::size_t k = 0; k < names.size(); ++k) {
                RenderOptions o = base;
                o.cache = sweptCaches()[k / std::size(kOrders)];
                o.order = kOrders[k % std::size(kOrders)];
                o.shading.sampling.spp = counts[i];
                RenderSession session(scene, o);
                const double start = threadSeconds();
                session.run();
                const double t = threadSeconds() - start;
                if (r == 0 || t < seconds[i][k]) seconds[i][k] = t;
                if (r == 0 && k == 0) {
                    error[i] = rmse(session.image(), reference);
                    rays[i] = session.counters().totalRays();
                }
            }
        for (std::size_t k = 0; k < names.size(); ++k)
            csv << "stochastic," << toString(sweptCaches()[k / std::size(kOrders)]) << ','
                << toString(kOrders[k % std::size(kOrders)]) << ',' << rays[i] << ',' << counts[i] << ','
                << seconds[i][k] << ',' << error[i] << '\n';
    }
    // The table: RMSE and seconds by sample count
    std::printf("%-22s", "spp");
    for (int n : counts) std::printf(" %8d", n);
    std::printf("\n%-22s", "RMSE");
    for (double e : error) std::printf(" %8.5f", e);
    std::printf("\n");
    for (std::size_t k = 0; k < names.size(); ++k) {
        std::printf("%-22s", names[k].c_str());
        for (std::size_t i = 0; i < counts.size(); ++i) std::printf(" %7.3fs", seconds[i][k]);
        std::printf("\n");
    }
    // Every configuration reaches the same error at the same sample count: the first to reach
    // it is the fastest at that count
    std::printf("\nFirst to reach each error (the fastest configuration at that sample count, and how much\n"
                "longer no cache in scanline order takes):\n\n");
    for (std::size_t i = 0; i < counts.size(); ++i) {
        const auto best = std::min_element(seconds[i].begin(), seconds[i].end()) - seconds[i].begin();
        std::printf("  RMSE %.5f (%3d spp): %-22s %7.3f s  (no cache, scanline: %.2fx)\n", error[i], counts[i],
                    names[std::size_t(best)].c_str(), seconds[i][std::size_t(best)],
                    seconds[i][0] / seconds[i][std::size_t(best)]);
    }
    // [stochastic-convergence]
    const std::string title = scene->name + " at " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                              ": stochastic error against run time";
    return writeTableAndChart(csv.str(), a.csv, a.plot, "plot_stochastic.py", title);
}

int convergence(const ConvergenceArgs& a) {
    if (a.stochastic) return stochastic(a);
    auto scene = std::make_shared<const Scene>(loadScene(a.scene, a.flags.seed));
    RenderOptions base = a.flags.options();
    base.shading.sampling = Sampling{};  // the sampling flags are --stochastic's
    if (base.width <= 0 && base.height <= 0) {
        // Default: the scene's size, at most 128 on the longer side
        const int w = scene->camera.width, h = scene->camera.height, m = std::max(w, h);
        base.width = m > 128 ? std::max(1, w * 128 / m) : w;
        base.height = m > 128 ? std::max(1, h * 128 / m) : h;
    }
    // The final image every partial one is measured against
    RenderSession first(scene, base);
    first.run();
    base.width = first.width();
    base.height = first.height();
    const LinearImage final = linearImage(first.image());
    const std::int64_t total = first.steps();

    // Progressive convergence: RMSE as each configuration's render proceeds
    std::ostringstream csv;
    csv << "kind,cache,order,steps,spp,seconds,rmse\n";
    std::printf("%s at %dx%d, depth %d, band %d: %lld rays.\n\nRMSE of the partial image against the final one "
                "as rendering proceeds (values clamped to [0, 1];\nunvisited pixels are black; %d samples per run, "
                "the fastest of %d runs): at 10%% ... 75%% of the\nrays, and the mean over the run by rays traced "
                "and by seconds:\n\n",
                scene->name.c_str(), base.width, base.height, base.shading.maxDepth, base.band, (long long)total,
                a.samples, a.repeat);
    std::printf("%-22s %8s %8s %8s %8s %8s %10s %10s\n", "cache, order", "seconds", "10%", "25%", "50%", "75%",
                "mean/rays", "mean/time");
    for (CacheKind c : sweptCaches())
        for (OrderKind o : kOrders) {
            RenderOptions opt = base;
            opt.cache = c;
            opt.order = o;
            // The least disturbed of a few runs: the machine is shared
            std::vector<ProgressPoint> pts;
            for (int r = 0; r < a.repeat; ++r) {
                std::vector<ProgressPoint> run = traceProgress(scene, opt, final, total, a.samples);
                if (pts.empty() || run.back().seconds < pts.back().seconds) pts = std::move(run);
            }
            const std::string name = std::string(toString(c)) + ", " + std::string(toString(o));
            std::printf("%-22s %8.4f %8.4f %8.4f %8.4f %8.4f %10.4f %10.4f\n", name.c_str(), pts.back().seconds,
                        at(pts, 0.10), at(pts, 0.25), at(pts, 0.50), at(pts, 0.75), meanOver(pts, false),
                        meanOver(pts, true));
            std::fflush(stdout);
            for (const ProgressPoint& p : pts)
                csv << "progress," << toString(c) << ',' << toString(o) << ',' << p.steps << ",1," << p.seconds << ','
                    << p.rmse << '\n';
        }

    // Supersampling against a high-sample reference
    RenderOptions fast = base;
    fast.cache = CacheKind::BlockerPlus;
    fast.order = OrderKind::BreadthFirst;
    double refSeconds = 0.0;
    const LinearImage reference = averageImage(scene, fast, gridOffsets(a.refGrid), &refSeconds);
    const std::vector<glm::dvec2> offsets = jitterOffsets(a.spp, a.jitterSeed);
    std::printf("\nJittered supersampling (Halton 2,3 offsets, one per render, averaged; the configurations take\n"
                "turns sample by sample) against a reference of %d x %d = %d regular samples per pixel\n"
                "(%.2f s): RMSE and seconds at each sample count:\n\n",
                a.refGrid, a.refGrid, a.refGrid * a.refGrid, refSeconds);
    // The configurations take turns, sample by sample, so that the machine's load falls
    // on all of them alike
    std::vector<SuperSampler> samplers;
    std::vector<std::string> names;
    for (CacheKind c : sweptCaches())
        for (OrderKind o : kOrders) {
            RenderOptions opt = base;
            opt.cache = c;
            opt.order = o;
            samplers.emplace_back(scene, opt, reference);
            names.push_back(std::string(toString(c)) + ", " + std::string(toString(o)));
        }
    for (std::size_t i = 0; i < offsets.size(); ++i)
        for (SuperSampler& s : samplers) s.add(offsets[i], i + 1 == offsets.size());
    std::vector<std::vector<SupersamplePoint>> curves;
    for (std::size_t k = 0; k < samplers.size(); ++k) {
        curves.push_back(samplers[k].points());
        const CacheKind c = sweptCaches()[k / 3];
        const OrderKind o = kOrders[k % 3];
        for (const SupersamplePoint& p : curves.back())
            csv << "supersample," << toString(c) << ',' << toString(o) << ",0," << p.spp << ',' << p.seconds << ','
                << p.rmse << '\n';
    }
    // The table: RMSE and seconds by sample count
    std::printf("%-6s %8s", "spp", "RMSE");
    for (const std::string& n : names) std::printf(" %9.9s", n.c_str());
    std::printf("\n%-6s %8s", "", "");
    for (const std::string& n : names) std::printf(" %9.9s", n.c_str() + std::min<std::size_t>(n.size(), 10));
    std::printf("\n");
    for (std::size_t i = 0; i < curves[0].size(); ++i) {
        std::printf("%-6d %8.5f", curves[0][i].spp, curves[0][i].rmse);
        for (const auto& curve : curves) std::printf(" %8.3fs", curve[i].seconds);
        std::printf("\n");
    }

    const std::string title = scene->name + " at " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                              ": error against run time";
    return writeTableAndChart(csv.str(), a.csv, a.plot, "plot_convergence.py", title);
}

}  // namespace

void addConvergenceCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<ConvergenceArgs>();
    CLI::App* c = app.add_subcommand("convergence", "error against run time: partial images and supersampling, "
                                                    "every cache and order");
    c->add_option("scene", a->scene, "an .nff file or a built-in such as cube:5")->required();
    c->add_option("--csv", a->csv, "write every sample as CSV")->check(outputFile());
    c->add_option("--plot", a->plot, "draw the chart (.png or .svg) with matplotlib")->check(outputFile());
    c->add_option("--spp", a->spp, "most jittered samples per pixel (--stochastic: at most 256)")->check(CLI::Range(1, 1024))
        ->capture_default_str();
    c->add_flag("--stochastic", a->stochastic,
                "distributed ray tracing at 1, 2, 4, ... --spp pixel samples (with --light-radius, --gloss ...): "
                "RMSE against a --ref-spp reference, against seconds");
    c->add_option("--ref-spp", a->refSpp, "--stochastic: pixel samples of the reference")
        ->check(CLI::Range(1, kMaxSpp))->capture_default_str();
    c->add_option("--ref-grid", a->refGrid, "the reference takes ref-grid^2 regular samples per pixel")
        ->check(CLI::Range(1, 64))->capture_default_str();
    c->add_option("--repeat", a->repeat, "runs of each progress curve; the fastest is kept")
        ->check(CLI::Range(1, 100))->capture_default_str();
    c->add_option("--samples", a->samples, "RMSE samples per progressive run")->check(CLI::Range(2, 100000))
        ->capture_default_str();
    // The whole image is one band by default: progressive order then shows the hidden-surface
    // view of the whole image first, as the paper's conclusion describes
    a->flags.band = 0;
    a->flags.addTo(c, false);
    // --stochastic only: soft shadows and gloss, one sample of each per pixel sample (Cook's
    // distributed ray tracing), so that noise falls as the pixel samples grow
    a->flags.sampling.lightRadius = 0.3;
    a->flags.sampling.glossDegrees = 5.0;
    a->flags.addSamplingTo(c, false);
    out.push_back({c, [a] { return convergence(*a); }});
}

}  // namespace rc::cli
