#pragma once
/// \file
/// \brief A render: scene, cache strategy and order tied together, advanced one ray per step.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "order/ray_order.h"
#include "render/session_checkpoint.h"
#include "search/accelerator.h"
#include "search/cache_strategy.h"
#include "search/linear_search.h"
#include "trace/shading.h"
#include "trace/trace_event.h"

namespace rc {

/// RenderOptions::band: chosen by the complete search and the cache (bandFor()).
inline constexpr int kAutoBand = -1;

/// The band an order works in when none is asked for. Breadth-first order keeps a band's rays of a
/// generation in memory, and they are written and read back once each. In front of the linear scan
/// a complete search is dear, and regions of several scanlines save searches: 8 scanlines save about
/// as many as 16 and hold half the memory (a band of 16 at 512 wide outgrows a second-level cache of
/// 1 MB). In front of a grid, a BVH or Embree a search is cheap and the memory is what costs: 1
/// scanline. Nor does a cache that defers no miss gain from large regions: blocker+dir answers its
/// misses from lists, so 1 scanline too. `raycache table1` and `raycache bench --band` measure it.
int bandFor(AccelKind accel, CacheKind cache);

/// Everything a render is told.
struct RenderOptions {
    int width = 0;    ///< 0: the scene's own resolution
    int height = 0;
    CacheKind cache = CacheKind::None;
    AccelKind accel = AccelKind::Linear;  ///< what answers complete searches
    OrderKind order = OrderKind::Scanline;
    ShadingOptions shading;
    /// Scanlines per band in breadth-first and progressive orders (0: all; kAutoBand: by
    /// the complete search and the cache, see bandFor())
    int band = kAutoBand;
    bool verify = false;  ///< run the complete search beside every cached answer
    /// Trace only scanlines [rowBegin, rowEnd) (rowEnd 0: to the bottom). Parallel renders
    /// give each thread its own rows; the image keeps its full size.
    int rowBegin = 0;
    int rowEnd = 0;
    /// Added to every pixel's position before its eye ray is made: supersampling jitter,
    /// in pixels. (0, 0), the default, leaves every eye ray as it is.
    glm::dvec2 pixelOffset{0.0, 0.0};
    /// Distributed ray tracing's samples: one path each; whether they share entries.
    /// Shared by default: in scanline and progressive order the samples of a pixel follow
    /// each other, so a shared entry answers each with what the one before found;
    /// breadth-first order is the same either way (see cache_tree.h).
    SampleEntries sampleEntries = SampleEntries::Shared;
    /// Breadth-first order: make room for a band of rays in each path as it is met, so no
    /// path grows by copying into fresh memory (faster natively, where room never filled
    /// costs nothing). False: paths grow as they fill, for a render whose memory holds all
    /// it is given (the web page's: WebAssembly memory is resident once allocated and never
    /// shrinks). The rays and the image are the same either way.
    bool reserveRays = true;
};

/// A render in progress. `step()` traces exactly one ray: the order picks it, the cache
/// strategy answers it at its ray-tree path, shading adds to its pixel and spawns its
/// children, and every attached sink hears about it.
class RenderSession {
public:
    RenderSession(std::shared_ptr<const Scene> scene, RenderOptions options);
    /// A render whose complete searches are made by `search` instead of `options.accel`'s.
    RenderSession(std::shared_ptr<const Scene> scene, RenderOptions options, std::unique_ptr<CompleteSearch> search);
    ~RenderSession();

    /// Traces one ray. Returns false when the image is complete.
    bool step();
    /// Traces the rest. `progress(done fraction)` is called now and then; it returns
    /// false to stop early (cancel). Returns true when the image is complete.
    bool run(const std::function<bool(double)>& progress = {});
    bool done() const { return done_; }

    /// Attaches a sink; it must outlive the session or be removed.
    void addSink(TraceSink* sink) { sinks_.push_back(sink); }
    void removeSink(TraceSink* sink);

    const Scene& scene() const { return *scene_; }
    std::shared_ptr<const Scene> scenePtr() const { return scene_; }
    const RenderOptions& options() const { return options_; }
    int width() const { return options_.width; }
    int height() const { return options_.height; }
    const Counters& counters() const { return counters_; }
    /// What answers its complete searches.
    const CompleteSearch& completeSearch() const { return *search_; }
    const ImageAccumulator& image() const { return image_; }
    /// Hands the image over (the session's is left empty): no copy of a finished render.
    ImageAccumulator takeImage() { return std::move(image_); }
    const CacheTree& cacheTree() const { return paths_; }
    const CacheStrategy& strategy() const { return *strategy_; }
    const RayOrder& order() const { return *order_; }
    /// Rays traced so far (deferred attempts not included).
    std::int64_t steps() const { return steps_; }
    /// The eye ray of a pixel (of pixel sample `sample`, jittered when there are several).
    Ray primaryRay(int pixel, int sample = 0) const;
    /// The eye ray task of a pixel sample, with its path in the cache tree, made in `t`.
    void eyeTask(int pixel, int sample, RayTask& t);
    /// Eye rays not yet started, as a fraction of all pixels (for progress).
    double progress() const;

    // [session-checkpoint]
    /// The render as it is now, to come back to with restore(). Scanlines of the image
    /// equal to those of `previous` (an earlier checkpoint of this session, or null) are
    /// shared with it.
    SessionCheckpoint checkpoint(const SessionCheckpoint* previous = nullptr) const;
    /// checkpoint() into `c`, an old checkpoint of this session no longer wanted: its
    /// memory is reused (fresh memory is what a checkpoint costs most).
    void checkpointInto(SessionCheckpoint& c, const SessionCheckpoint* previous) const;
    /// Goes back to a checkpoint this session took, exactly: stepping on from it traces
    /// the same rays, with the same answers, counters and image, as it did the first time.
    /// The session must be at or past it (the blocker lists are kept as a log that only
    /// grows): throws std::invalid_argument otherwise. Sinks hear nothing of it.
    void restore(const SessionCheckpoint& c);
    // [session-checkpoint]

private:
    std::shared_ptr<const Scene> scene_;
    RenderOptions options_;
    RayGenerator camera_;
    std::unique_ptr<CompleteSearch> search_;
    LinearSearch verifier_;  ///< --verify compares against the plain scan
    std::unique_ptr<CacheStrategy> strategy_;
    std::unique_ptr<RayOrder> order_;
    CacheTree paths_;
    ImageAccumulator image_;
    Counters counters_;
    std::vector<TraceSink*> sinks_;
    std::vector<RayTask> children_;
    std::int64_t steps_ = 0;
    std::int64_t primaries_ = 0;
    bool done_ = false;
};

}  // namespace rc
