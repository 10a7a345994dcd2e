#include "study/stability.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "analysis/median.h"
#include "search/standard_algorithm.h"
#include "study/precise_intersection.h"

namespace rc {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool hasNaN(const Vec3& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z); }

/// Marks pixels that a NaN or an infinity reached: through a ray, a weight (for a shadow
/// ray, the light it carries), or a hit distance.
class NonFiniteProbe final : public TraceSink {
public:
    explicit NonFiniteProbe(int pixels) : nan(pixels, 0), inf(pixels, 0) {}
    void onEvent(const TraceEvent& e) override {
        const RayTask& t = e.task;
        const Vec3 values[] = {t.query.ray.o, t.query.ray.d, t.weight};
        for (const Vec3& v : values) {
            if (hasNaN(v)) nan[t.pixel] = 1;
            else if (!finite(v)) inf[t.pixel] = 1;
        }
        const double hit = e.lookup.answer().t;
        if (std::isnan(hit)) nan[t.pixel] = 1;
        if (e.lookup.answer().object >= 0 && !std::isfinite(hit)) inf[t.pixel] = 1;
    }
    std::vector<std::uint8_t> nan, inf;
};

/// Hit distances against the long double reference, and shadow acne.
class PrecisionProbe final : public TraceSink {
public:
    PrecisionProbe(const Scene& s, int pixels) : scene_(s), acne(pixels, 0) {}
    void onEvent(const TraceEvent& e) override {
        if (e.deferred) return;
        const Query& q = e.task.query;
        const Answer& a = e.lookup.answer();
        if (a.object < 0) return;
        if (q.kind == RayKind::Shadow) {
            const double scale = std::max({std::abs(q.ray.o.x), std::abs(q.ray.o.y), std::abs(q.ray.o.z)});
            // The surface the ray leaves outward: the one the complete search's test
            // (rc::standardTest, tutorial 01's hole) passes over without a counted test
            Counters tested;
            Answer unused;
            standardTest(scene_, q, a.object, unused, tested);
            const bool self = tested.intersectionTests == 0;
            if (self || a.t < 1e-9 * scale) {
                // Acne: counted here, and kept out of the distance errors (a root at the
                // rounding level of the origin has no relative accuracy to speak of)
                ++acneRays;
                acne[e.task.pixel] = 1;
                return;
            }
        }
        const long double ref = preciseHit(scene_, q.ray, a.object, q.origin);
        if (!std::isfinite(double(ref))) ++flips;
        else errors.push_back(double(std::abs((long double)a.t - ref) / std::abs(ref)));
    }
    const Scene& scene_;
    std::vector<double> errors;
    std::uint64_t flips = 0;
    std::uint64_t acneRays = 0;
    std::vector<std::uint8_t> acne;
};

}  // namespace

SceneStability checkStability(const StiffScene& s, int depth) {
    SceneStability out;
    out.name = s.name;
    out.description = s.description;
    out.objects = s.scene->size();
    std::vector<Vec3> reference;
    std::vector<std::uint8_t> nan, inf, differ;
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
        for (CacheKind cache : allCacheKinds()) {
            for (OrderKind order : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst}) {
                RenderOptions o;
                o.accel = accel;
                o.cache = cache;
                o.order = order;
                o.shading.maxDepth = depth;
                o.verify = cache != CacheKind::None;
                RenderSession session(s.scene, o);
                const int pixels = session.width() * session.height();
                if (nan.empty()) {
                    out.width = session.width();
                    out.height = session.height();
                    nan.assign(pixels, 0);
                    inf.assign(pixels, 0);
                    differ.assign(pixels, 0);
                }
                NonFiniteProbe finiteProbe(pixels);
                PrecisionProbe precision(*s.scene, pixels);
                session.addSink(&finiteProbe);
                const bool first = reference.empty();
                if (first) session.addSink(&precision);
                const auto start = std::chrono::steady_clock::now();
                session.run();
                StabilityRun run;
                run.accel = accel;
                run.cache = cache;
                run.order = order;
                run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                const Counters& n = session.counters();
                run.rays = n.totalRays();
                run.intersectionTests = n.intersectionTests;
                run.completeSearches = n.completeSearches;
                run.disagreements = n.verifyDisagreements;
                for (int p = 0; p < pixels; ++p) {
                    const Vec3 v = session.image().value(p);
                    // A NaN or infinity summed in fixed point shows up as a wild value
                    if (!finite(v) || std::abs(v.x) + std::abs(v.y) + std::abs(v.z) > 1e6) {
                        ++run.nonFinitePixels;
                        inf[p] |= !finiteProbe.nan[p];
                    }
                    nan[p] |= finiteProbe.nan[p];
                    inf[p] |= finiteProbe.inf[p];
                    if (first) {
                        reference.push_back(v);
                    } else if (!(v == reference[p])) {
                        ++run.differingPixels;
                        differ[p] = 1;
                    }
                }
                if (first) {
                    std::vector<double>& e = precision.errors;
                    out.hitsChecked = e.size() + precision.flips;
                    out.hitFlips = precision.flips;
                    if (!e.empty()) {
                        out.maxRelTError = *std::max_element(e.begin(), e.end());
                        out.medianRelTError = median(e);
                    }
                    out.acneRays = precision.acneRays;
                    out.acnePixels = std::count(precision.acne.begin(), precision.acne.end(), 1);
                }
                out.disagreements += run.disagreements;
                out.seconds += run.seconds;
                out.runs.push_back(run);
            }
        }
    }
    out.nanPixels = std::count(nan.begin(), nan.end(), 1);
    out.infPixels = std::count(inf.begin(), inf.end(), 1);
    out.differingPixels = std::count(differ.begin(), differ.end(), 1);
    return out;
}

}  // namespace rc
