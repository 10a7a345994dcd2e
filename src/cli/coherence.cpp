/// \file
/// \brief `raycache coherence SCENE --sweep light-radius|gloss|spp`: the caches as rays spread.
/// "If rays were randomly chosen ... we would expect few cache hits" (Hanrahan 1986): for each
/// value of one distributed ray tracing parameter, every cache in every order renders the same
/// rays, and the table says how often each cache still answers, how many complete searches it
/// makes per ray and per beam, the beam tree's coherence, and its tests and time against the
/// plain tracer (no cache, scanline order).
#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "analysis/beam_tree.h"
#include "analysis/median.h"
#include "cli/commands.h"
#include "search/cache_registry.h"
#include "cli/cpu_clock.h"
#include "cli/plot_script.h"
#include "render/output_files.h"
#include "scene/builtin_scenes.h"

namespace rc::cli {

namespace {

struct CoherenceArgs {
    std::string scene, sweep, csv, plot;
    std::vector<double> values;
    int repeat = 3;
    RenderFlags flags;
};

// The registered caches that the sweeps take (search/cache_registry.h), read when first
// asked, after every registrar has run
const std::vector<CacheKind>& sweptCaches() {
    static const std::vector<CacheKind> swept = sweptCacheKinds();
    return swept;
}
const OrderKind kOrders[] = {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst};

// [coherence-defaults]
// The values swept when none are given: from almost no spread to far more than the spacing
// of cube:N's spheres. Radius and gloss start just above 0, not at 0: at 0 the samples
// collapse into one ray, and a row with other rays would not compare with the rest
std::vector<double> defaultValues(const std::string& sweep) {
    if (sweep == "light-radius") return {0.01, 0.03, 0.1, 0.3, 1.0, 3.0};
    if (sweep == "gloss") return {0.1, 0.3, 1.0, 3.0, 10.0, 30.0};
    return {1.0, 2.0, 4.0, 8.0, 16.0};  // spp
}
// [coherence-defaults]

struct Measure {
    Counters n;
    std::vector<double> seconds;
};

int coherence(const CoherenceArgs& a) {
    // The scene and the image size (96x96 unless given)
    auto scene = std::make_shared<const Scene>(loadScene(a.scene, a.flags.seed));
    RenderFlags flags = a.flags;
    if (flags.width <= 0 && flags.height <= 0) flags.width = flags.height = 96;
    if (flags.width <= 0) flags.width = flags.height;
    if (flags.height <= 0) flags.height = flags.width;
    const std::vector<double> values = a.values.empty() ? defaultValues(a.sweep) : a.values;
    // Every value is checked before any rendering
    for (double v : values) {
        RenderOptions o = flags.options();
        if (a.sweep == "light-radius") o.shading.sampling.lightRadius = v;
        else if (a.sweep == "gloss") o.shading.sampling.glossDegrees = v;
        else if (v != double(int(v))) throw std::invalid_argument("--values for spp must be whole numbers");
        else o.shading.sampling.spp = int(v);
        if (const auto e = samplingError(o.shading.sampling, o.shading.maxDepth))
            throw std::invalid_argument("--values " + std::to_string(v) + ": " + *e);
    }

    // The CSV's header and the table's preamble
    std::ostringstream csv;
    csv << "sweep,value,rays,rays_per_pixel,beam_nodes,rays_per_beam,coherence,none_seconds,none_tests";
    for (CacheKind c : sweptCaches())
        for (OrderKind o : kOrders)
            for (const char* m : {"hit_rate", "searches_per_ray", "searches_per_beam", "tests_ratio", "time_ratio"})
                csv << ',' << toString(c) << '_' << toString(o) << '_' << m;
    csv << '\n';
    const Sampling& s = flags.sampling;
    std::printf("%s at %dx%d, depth %d, seed %llu; sweeping %s (spp %d, light radius %g with %d shadow samples, "
                "gloss %g degrees with %d samples, entries %s, accel %s, %d run%s per time).\n"
                "Hit rate: rays the cache answered with what it held; searches: complete searches per ray and\n"
                "per beam-tree node; tests and time (thread CPU time): against no cache in scanline order.\n",
                scene->name.c_str(), flags.width, flags.height, flags.depth, (unsigned long long)flags.seed,
                a.sweep.c_str(), s.spp, s.lightRadius, s.shadowSamples, s.glossDegrees, s.glossSamples,
                flags.sampleEntries.c_str(), flags.accel.c_str(), a.repeat, a.repeat > 1 ? "s" : "");
    // The first value at which each configuration stops paying, in tests and in time
    std::map<std::string, std::pair<double, double>> stops;
    for (double v : values) {
        // Render every configuration at this value
        RenderOptions base = flags.options();
        if (a.sweep == "light-radius") base.shading.sampling.lightRadius = v;
        else if (a.sweep == "gloss") base.shading.sampling.glossDegrees = v;
        else base.shading.sampling.spp = int(v);
        std::vector<Measure> m(sweptCaches().size() * std::size(kOrders));
        auto configuration = [&](std::size_t k) {
            RenderOptions o = base;
            o.cache = sweptCaches()[k / std::size(kOrders)];
            o.order = kOrders[k % std::size(kOrders)];
            return o;
        };
        // The beam tree (the rays are the same for every configuration) from a render of
        // its own: a render that feeds a sink is slower, so no timed render does
        BeamTreeStats beams;
        {
            RenderSession session(scene, configuration(0));
            BeamTreeBuilder builder(session.width(), session.height());
            session.addSink(&builder);
            session.run();
            beams = builder.build();
        }
        // Interleaved, as table1 does: each repeat renders every configuration once
        for (int r = 0; r < a.repeat; ++r)
            for (std::size_t k = 0; k < m.size(); ++k) {
                RenderSession session(scene, configuration(k));
                const double start = threadSeconds();
                session.run();
                m[k].seconds.push_back(threadSeconds() - start);
                m[k].n = session.counters();
            }
        // One row per configuration, against no cache in scanline order
        const double t0 = median(m[0].seconds);
        const double tests0 = double(m[0].n.intersectionTests);
        const double rays = double(m[0].n.totalRays());
        const double perBeamRays = beams.nodes ? rays / double(beams.nodes) : 0.0;
        std::printf("\n%s = %g: %.0f rays (%.1f per pixel), beam tree %lld nodes (%.2f rays each), coherence %.3g; "
                    "no cache %.3f s\n",
                    a.sweep.c_str(), v, rays, rays / (double(flags.width) * flags.height), (long long)beams.nodes,
                    perBeamRays, beams.coherence, t0);
        std::printf("  %-22s %9s %12s %13s %7s %7s\n", "cache, order", "hit rate", "search/ray", "search/beam", "tests",
                    "time");
        csv << a.sweep << ',' << v << ',' << rays << ',' << rays / (double(flags.width) * flags.height) << ','
            << beams.nodes << ',' << perBeamRays << ',' << beams.coherence << ',' << t0 << ',' << m[0].n.intersectionTests;
        for (std::size_t k = 0; k < m.size(); ++k) {
            const Counters& n = m[k].n;
            const double hit = double(n.hits) / rays;
            const double perRay = double(n.completeSearches) / rays;
            const double perBeam = beams.nodes ? double(n.completeSearches) / double(beams.nodes) : 0.0;
            const double tests = double(n.intersectionTests) / tests0;
            const double time = median(m[k].seconds) / t0;
            const std::string name = std::string(toString(sweptCaches()[k / std::size(kOrders)])) + ", " +
                                     std::string(toString(kOrders[k % std::size(kOrders)]));
            std::printf("  %-22s %9.3f %12.3f %13.2f %7.3f %7.3f\n", name.c_str(), hit, perRay, perBeam, tests, time);
            csv << ',' << hit << ',' << perRay << ',' << perBeam << ',' << tests << ',' << time;
            auto it = stops.try_emplace(name, -1.0, -1.0).first;
            if (it->second.first < 0.0 && tests >= 1.0) it->second.first = v;
            if (it->second.second < 0.0 && time >= 1.0) it->second.second = v;
        }
        csv << '\n';
        std::fflush(stdout);
    }
    // Where each configuration stops paying
    std::printf("\nWhere each cache stops paying: the first %s at which it makes at least as many tests, or\n"
                "takes at least as long, as no cache in scanline order (- : it pays at every value swept):\n\n",
                a.sweep.c_str());
    std::printf("  %-22s %10s %10s\n", "cache, order", "tests", "time");
    for (std::size_t k = std::size(kOrders); k < sweptCaches().size() * std::size(kOrders); ++k) {
        const std::string name = std::string(toString(sweptCaches()[k / std::size(kOrders)])) + ", " +
                                 std::string(toString(kOrders[k % std::size(kOrders)]));
        const auto [tests, time] = stops[name];
        auto shown = [](double x) { return x < 0.0 ? std::string("-") : (std::ostringstream() << x).str(); };
        std::printf("  %-22s %10s %10s\n", name.c_str(), shown(tests).c_str(), shown(time).c_str());
    }

    // The CSV and the chart
    const std::string title = scene->name + " at " + std::to_string(flags.width) + "x" + std::to_string(flags.height) +
                              ": the caches as " + a.sweep + " grows";
    return writeTableAndChart(csv.str(), a.csv, a.plot, "plot_coherence.py", title);
}

}  // namespace

void addCoherenceCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<CoherenceArgs>();
    CLI::App* c = app.add_subcommand("coherence", "the caches as rays spread: sweep light radius, gloss or spp "
                                                  "and compare every cache and order");
    c->add_option("scene", a->scene, "an .nff file or a built-in such as cube:5")->required();
    c->add_option("--sweep", a->sweep, "the parameter swept: light-radius | gloss | spp")
        ->required()->check(CLI::IsMember({"light-radius", "gloss", "spp"}));
    c->add_option("--values", a->values, "its values, e.g. 0.1,0.3,1 (default: 5 or 6 values from narrow to wide)")
        ->delimiter(',');
    c->add_option("--csv", a->csv, "write one row per value as CSV")->check(outputFile());
    c->add_option("--plot", a->plot, "draw the chart (.png or .svg) with matplotlib")->check(outputFile());
    c->add_option("--repeat", a->repeat, "runs of each configuration; times are medians")
        ->check(CLI::Range(1, 100))->capture_default_str();
    // Spread needs samples: 4 shadow rays per light, 2 glossy rays per hit unless told
    a->flags.sampling.shadowSamples = 4;
    a->flags.sampling.glossSamples = 2;
    a->flags.addTo(c, false);
    a->flags.addSamplingTo(c, true);
    out.push_back({c, [a] { return coherence(*a); }});
}

}  // namespace rc::cli
