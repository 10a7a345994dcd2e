/// \file
/// \brief `raycache stability`: the stiff and extreme scene suite rendered with every cache and
/// order, checked for NaN, disagreements and precision; `--intersection` compares the
/// textbook and stable ray-sphere formulas in float and double against long double.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "study/precise_intersection.h"
#include "study/stability.h"
#include "study/stiff_scenes.h"
#include "cli/commands.h"
#include "render/output_files.h"

namespace rc::cli {

namespace {

struct StabilityArgs {
    std::string suite, json, only;
    bool intersection = false;
    int depth = 5;
    int rays = 4096;
};

int intersectionTable(const StabilityArgs& a) {
    const std::vector<IntersectionRow> rows = compareIntersections(a.rays);
    std::printf("Ray-sphere intersection, %d seeded rays per case: relative error of the nearest hit t\n"
                "against the stable formula in long double (x87, 64-bit mantissa) on the same double\n"
                "inputs; 'wrong' counts rays called a hit where the reference misses, or the reverse.\n"
                "The long double row of each case is the stable formula taking |d| = 1, as the double\n"
                "code does: how far that assumption alone moves t.\n\n",
                a.rays);
    for (const auto& [name, why] : intersectionCases()) std::printf("  %-24s %s\n", name.c_str(), why.c_str());
    std::printf("\n%-24s %-9s %-11s %10s %10s %7s %8s\n", "case", "formula", "precision", "max rel", "median",
                "wrong", "ns/test");
    std::string last;
    nlohmann::json j = nlohmann::json::array();
    for (const IntersectionRow& r : rows) {
        if (r.stiffCase != last && !last.empty()) std::printf("\n");
        std::printf("%-24s %-9s %-11s %10.1e %10.1e %7lld %8.1f\n", r.stiffCase == last ? "" : r.stiffCase.c_str(),
                    r.formula.c_str(), r.precision.c_str(), r.maxRelError, r.medianRelError, (long long)r.wrongHits,
                    r.nsPerTest);
        last = r.stiffCase;
        j.push_back({{"case", r.stiffCase},
                      {"formula", r.formula},
                      {"precision", r.precision},
                      {"max_rel_error", r.maxRelError},
                      {"median_rel_error", r.medianRelError},
                      {"rays", r.rays},
                      {"wrong_hits", r.wrongHits},
                      {"ns_per_test", r.nsPerTest}});
    }
    if (!a.json.empty()) writeTextFile(a.json, j.dump(2) + "\n");
    return 0;
}

int stability(const StabilityArgs& a) {
    if (a.intersection) return intersectionTable(a);
    const std::string dir = a.suite.empty() ? defaultStiffSuiteDir() : a.suite;
    const std::vector<StiffScene> suite = loadStiffSuite(dir);
    std::printf("Stability suite: %zu scenes (%s), each rendered in front of searches linear, grid, bvh\n"
                "with caches none, cylinder, blocker, blocker+, blocker+dir and orders scanline,\n"
                "progressive, bfs (45 runs; cached runs verify every answer).\n"
                "differ: pixels unlike linear/none/scanline's, bit for bit; t err: relative error of hit\n"
                "distances against long double; flips: hits the reference calls misses; acne: pixels\n"
                "with a shadow ray blocked by its own surface or nearer than 1e-9 |origin|.\n\n",
                suite.size(), dir.empty() ? "generators only" : ("generators + " + dir).c_str());
    std::printf("%-20s %4s %5s %4s %4s %6s %8s %9s %9s %5s %5s %7s  %s\n", "scene", "objs", "size", "NaN", "Inf",
                "differ", "disagree", "max t err", "median", "flips", "acne", "seconds", "");
    nlohmann::json j = nlohmann::json::array();
    int failures = 0, checked = 0;
    for (const StiffScene& s : suite) {
        if (!a.only.empty() && s.name.find(a.only) == std::string::npos) continue;
        ++checked;
        const SceneStability r = checkStability(s, a.depth);
        failures += !r.ok();
        std::printf("%-20s %4d %2dx%-2d %4lld %4lld %6lld %8llu %9.1e %9.1e %5llu %5lld %7.3f  %s\n",
                    r.name.c_str(), r.objects, r.width, r.height, (long long)r.nanPixels, (long long)r.infPixels,
                    (long long)r.differingPixels, (unsigned long long)r.disagreements, r.maxRelTError,
                    r.medianRelTError, (unsigned long long)r.hitFlips, (long long)r.acnePixels, r.seconds,
                    r.ok() ? "ok" : "FAIL");
        std::fflush(stdout);
        nlohmann::json runs = nlohmann::json::array();
        for (const StabilityRun& run : r.runs)
            runs.push_back({{"accel", std::string(toString(run.accel))},
                            {"cache", std::string(toString(run.cache))},
                            {"order", std::string(toString(run.order))},
                            {"seconds", run.seconds},
                            {"rays", run.rays},
                            {"intersection_tests", run.intersectionTests},
                            {"complete_searches", run.completeSearches},
                            {"verify_disagreements", run.disagreements},
                            {"differing_pixels", run.differingPixels},
                            {"non_finite_pixels", run.nonFinitePixels}});
        j.push_back({{"scene", r.name},
                     {"description", r.description},
                     {"objects", r.objects},
                     {"width", r.width},
                     {"height", r.height},
                     {"nan_pixels", r.nanPixels},
                     {"inf_pixels", r.infPixels},
                     {"differing_pixels", r.differingPixels},
                     {"verify_disagreements", r.disagreements},
                     {"max_rel_t_error", r.maxRelTError},
                     {"median_rel_t_error", r.medianRelTError},
                     {"hits_checked", r.hitsChecked},
                     {"hit_flips", r.hitFlips},
                     {"acne_pixels", r.acnePixels},
                     {"acne_rays", r.acneRays},
                     {"seconds", r.seconds},
                     {"ok", r.ok()},
                     {"runs", runs}});
    }
    if (!a.json.empty()) writeTextFile(a.json, j.dump(2) + "\n");
    std::printf("\n%d of %d scenes %s\n", checked - failures, checked,
                failures ? "passed: NaN, infinities or disagreements above" : "passed: no NaN, no disagreements");
    return failures ? 1 : 0;
}

}  // namespace

void addStabilityCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<StabilityArgs>();
    CLI::App* c = app.add_subcommand("stability", "run the stiff-scene suite with every cache and order, "
                                                  "or compare intersection formulas (--intersection)");
    c->add_option("--suite", a->suite, "directory of stiff NFF scenes (default: tests/stiff of the source tree)");
    c->add_option("--json", a->json, "also write the results as JSON")->check(outputFile());
    c->add_option("--scene", a->only, "only the scenes whose name contains this");
    c->add_option("--depth", a->depth, "maximum ray-tree depth")->check(CLI::Range(1, 64))->capture_default_str();
    c->add_flag("--intersection", a->intersection,
                "textbook and stable ray-sphere formulas, float and double, against long double");
    c->add_option("--rays", a->rays, "rays per case for --intersection")->check(CLI::Range(16, 10000000))
        ->capture_default_str();
    out.push_back({c, [a] { return stability(*a); }});
}

}  // namespace rc::cli
