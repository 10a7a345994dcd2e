#pragma once
/// \file
/// \brief Renders a scene with every cache and order and checks what came out: NaN and
/// infinite values, pixels that differ between strategies, answers that differ from the
/// complete search, hit distances against a long double reference, and shadow acne.
#include <cstdint>
#include <string>
#include <vector>

#include "study/stiff_scenes.h"
#include "render/render_session.h"

namespace rc {

/// One render of the scene with one complete search, cache and order.
struct StabilityRun {
    AccelKind accel = AccelKind::Linear;  ///< the complete search
    CacheKind cache = CacheKind::None;
    OrderKind order = OrderKind::Scanline;
    double seconds = 0;
    std::uint64_t rays = 0;
    std::uint64_t intersectionTests = 0;
    std::uint64_t completeSearches = 0;
    std::uint64_t disagreements = 0;    ///< answers unlike the complete search's (--verify)
    std::int64_t differingPixels = 0;   ///< against linear/none/scanline, exactly
    std::int64_t nonFinitePixels = 0;
};

/// What the runs of one scene showed.
struct SceneStability {
    std::string name, description;
    int width = 0, height = 0, objects = 0;
    std::int64_t nanPixels = 0;        ///< a NaN reached the pixel (any run)
    std::int64_t infPixels = 0;        ///< an infinity reached the pixel (any run)
    std::int64_t differingPixels = 0;  ///< differ between strategies (any run)
    std::uint64_t disagreements = 0;   ///< summed over the cached runs
    /// Hit distances against preciseHit(): largest and median relative error over the
    /// hits both agree are hits, and the hits one calls a miss (a near-zero root whose
    /// sign the rounding decides, a ray that grazes a silhouette).
    double maxRelTError = 0, medianRelTError = 0;
    std::uint64_t hitsChecked = 0, hitFlips = 0;
    /// Shadow acne: pixels with a shadow ray blocked by the object it leaves (outward,
    /// which convexity forbids) or by any object nearer than 1e-9 times the magnitude of
    /// the ray's origin (10^7 ulps: nothing a rounded surface point can tell apart from
    /// its own surface).
    std::int64_t acnePixels = 0;
    std::uint64_t acneRays = 0;
    double seconds = 0;  ///< all runs
    std::vector<StabilityRun> runs;

    bool ok() const { return nanPixels == 0 && infPixels == 0 && disagreements == 0 && differingPixels == 0; }
};

/// Renders `s` in front of every complete search (linear, grid, bvh) with every cache
/// and order (scanline, progressive, bfs), cached runs with verify on.
SceneStability checkStability(const StiffScene& s, int depth = 5);

}  // namespace rc
