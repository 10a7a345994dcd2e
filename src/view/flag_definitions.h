#pragma once
/// \file
/// \brief The command-line options `raycache` and `raycache-gui` share, defined once: the
/// render's cache, order, complete search, size, band and distributed ray tracing's
/// samples, with the same names, help and limits (NffLimits::maxResolution, kMaxSpp, ...).
/// Header-only, in the viewer's layer: the GUI's command line and the tours read the same
/// options through view/viewer_settings.h.
#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "order/order_registry.h"
#include "scene/nff_reader.h"
#include "search/cache_registry.h"
#include "search/search_registry.h"
#include "trace/distributed_sampling.h"

namespace rc::cli {

/// "a (what a is) | b (what b is) | ...": a registry's names and descriptions, for a flag's help
template <class Entry>
std::string choices(const Registry<Entry>& r) {
    std::string out;
    for (const Entry& e : r.entries()) {
        if (!out.empty()) out += " | ";
        out += e.name + " (" + e.description + ")";
    }
    return out;
}

/// CLI::Range lets NaN through (no comparison with NaN is true), and inf through an open top
inline const CLI::Validator& finiteNumber() {
    static const CLI::Validator v([](std::string& s) -> std::string {
        return std::isfinite(std::strtod(s.c_str(), nullptr)) ? "" : "'" + s + "' is not a finite number";
    }, "", "Finite");
    return v;
}

/// --cache and --order: a registered name (search/cache_registry.h, order/order_registry.h)
inline CLI::Option* addCacheOption(CLI::App* c, std::string& cache) {
    return c->add_option("--cache", cache, choices(cacheRegistry()))->check(CLI::IsMember(cacheRegistry().names()));
}
inline CLI::Option* addOrderOption(CLI::App* c, std::string& order) {
    return c->add_option("--order", order, choices(orderRegistry()))->check(CLI::IsMember(orderRegistry().names()));
}

/// --accel: a registered complete search; with `exactOnly`, not one for comparison only
/// (the GUI draws what RayCache's own searches record)
inline CLI::Option* addAccelOption(CLI::App* c, std::string& accel, bool exactOnly) {
    std::vector<std::string> names;
    std::string help;
    for (const SearchInfo& s : searchRegistry().entries()) {
        if (exactOnly && s.comparisonOnly) continue;
        names.push_back(s.name);
        help += (help.empty() ? "" : " | ") + s.name + " (" + s.description + ")";
    }
    return c->add_option("--accel", accel, "complete search: " + help)->check(CLI::IsMember(names));
}

/// --width and --height, up to the largest resolution an NFF file may ask for
inline void addSizeOptions(CLI::App* c, int& width, int& height) {
    c->add_option("--width", width, "image width (default: the scene's)")->check(CLI::Range(1, int(NffLimits::maxResolution)));
    c->add_option("--height", height, "image height (default: the scene's)")->check(CLI::Range(1, int(NffLimits::maxResolution)));
}

/// --band: scanlines per band of breadth-first and progressive orders
inline CLI::Option* addBandOption(CLI::App* c, int& band) {
    return c->add_option("--band", band,
                         "scanlines per band in bfs and progressive orders (0: whole image; default: 8 in front of "
                         "the linear scan for a cache that defers its misses (cylinder, blocker, blocker+), else 1)")
        ->check(CLI::Range(0, int(NffLimits::maxResolution)));
}

/// Distributed ray tracing's samples: --light-radius --shadow-samples --gloss
/// --gloss-samples, and with `spp` also --spp, each within its documented limit.
inline void addSamplingOptions(CLI::App* c, Sampling& s, bool spp) {
    if (spp)
        c->add_option("--spp", s.spp, "pixel samples, stratified and jittered (distributed ray tracing)")
            ->check(CLI::Range(1, kMaxSpp))->capture_default_str();
    c->add_option("--light-radius", s.lightRadius, "lights become spheres of this radius: soft shadows (0: points)")
        ->check(finiteNumber())->check(CLI::NonNegativeNumber)->capture_default_str();
    c->add_option("--shadow-samples", s.shadowSamples, "shadow rays per light and hit when --light-radius > 0")
        ->check(CLI::Range(1, kMaxShadowSamples))->capture_default_str();
    c->add_option("--gloss", s.glossDegrees, "half-angle in degrees of the cone of glossy reflections (0: mirror)")
        ->check(finiteNumber())->check(CLI::Range(0.0, kMaxGlossDegrees))->capture_default_str();
    c->add_option("--gloss-samples", s.glossSamples, "reflection rays per hit when --gloss > 0")
        ->check(CLI::Range(1, kMaxGlossSamples))->capture_default_str();
}

}  // namespace rc::cli
