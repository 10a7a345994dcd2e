#include "render/render_session.h"

#include "order/deferral_policy.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

namespace {
RenderOptions resolved(const Scene& scene, RenderOptions o) {
    if (o.width <= 0) o.width = scene.camera.width;
    if (o.height <= 0) o.height = scene.camera.height;
    if (o.width <= 0 || o.height <= 0) throw std::invalid_argument("image size must be positive");
    if (o.shading.maxDepth < 1) throw std::invalid_argument("depth must be at least 1");
    if (o.rowEnd <= 0) o.rowEnd = o.height;
    if (o.band == kAutoBand) o.band = bandFor(o.accel, o.cache);
    if (o.band < 0) throw std::invalid_argument("a band must be 0 (the whole image) or more scanlines");
    if (o.rowBegin < 0 || o.rowBegin >= o.rowEnd || o.rowEnd > o.height)
        throw std::invalid_argument("rows must lie within the image and not be empty");
    if (const auto e = samplingError(o.shading.sampling, o.shading.maxDepth)) throw std::invalid_argument(*e);
    return o;
}
}  // namespace

int bandFor(AccelKind accel, CacheKind cache) {
    // [band-for]
    // Large regions where they save complete searches: in front of the linear scan, where
    // a search is dear, for a cache that defers its misses. Elsewhere, little memory
    const bool linear = accel == AccelKind::Linear;
    return linear && defersMisses(cache, !linear) ? 8 : 1;
    // [band-for]
}

RenderSession::RenderSession(std::shared_ptr<const Scene> scene, RenderOptions options)
    : RenderSession(std::move(scene), options, nullptr) {}

RenderSession::RenderSession(std::shared_ptr<const Scene> scene, RenderOptions options,
                             std::unique_ptr<CompleteSearch> search)
    : scene_(withLightRadius(std::move(scene), options.shading.sampling.lightRadius)),
      options_(resolved(*scene_, options)),
      camera_(scene_->camera, options_.width, options_.height),
      search_(search ? std::move(search) : makeCompleteSearch(options_.accel, *scene_)),
      verifier_(*scene_, LinearSearch::Regions::Scan),
      strategy_(makeStrategy(options_.cache, *scene_, *search_)),
      paths_(options_.sampleEntries),
      image_(options_.width, options_.height, options_.rowBegin, options_.rowEnd) {
    order_ = makeOrder(options_.order, options_.width, options_.rowBegin, options_.rowEnd, options_.band,
                       options_.shading.sampling.spp, defersMisses(options_.cache, search_->cheap()),
                       [this](int pixel, int sample, RayTask& t) {
                           ++primaries_;
                           eyeTask(pixel, sample, t);
                       });
    if (!options_.reserveRays) order_->roomAsNeeded();
}

RenderSession::~RenderSession() = default;

Ray RenderSession::primaryRay(int pixel, int sample) const {
    // [eye-sample]
    // One sample: the pixel's own position; several: stratified jitter around it
    const int spp = options_.shading.sampling.spp;
    const glm::dvec2 jitter =
        spp > 1 ? pixelSample(spp, sample, eyeKey(options_.shading.sampling.seed, pixel, sample)) : glm::dvec2(0.0);
    return camera_.primary(pixel % options_.width + options_.pixelOffset.x + jitter.x,
                           pixel / options_.width + options_.pixelOffset.y + jitter.y);
    // [eye-sample]
}

void RenderSession::eyeTask(int pixel, int sample, RayTask& t) {
    const int spp = options_.shading.sampling.spp;
    primaryTask(t, primaryRay(pixel, sample), pixel, sample, eyeKey(options_.shading.sampling.seed, pixel, sample),
                spp > 1 ? 1.0 / spp : 1.0);
    t.node = paths_.root(sample);
}

double RenderSession::progress() const {
    if (done_) return 1.0;
    return double(primaries_) / (double(options_.width) * (options_.rowEnd - options_.rowBegin) *
                                 options_.shading.sampling.spp);
}

void RenderSession::removeSink(TraceSink* sink) {
    sinks_.erase(std::remove(sinks_.begin(), sinks_.end(), sink), sinks_.end());
}

bool RenderSession::step() {
    if (done_) return false;
    while (std::optional<Pick> pick = order_->next()) {
        const RayTask& task = *pick->task;
        CacheEntry& entry = paths_.entry(task.node);
        // [session-step]
        // Ask the cache at this ray's path in the cache tree
        const std::uint64_t testsBefore = counters_.intersectionTests;
        const Lookup lookup = strategy_->lookup(task.query, entry, pick->mode, counters_);
        // What the sinks hear (made only when one listens)
        auto tell = [&](bool deferred) {
            if (sinks_.empty()) return;
            const int tests = int(counters_.intersectionTests - testsBefore);
            const TraceEvent event{steps_, task, lookup, tests, deferred};
            for (TraceSink* s : sinks_) s->onEvent(event);
        };
        if (!lookup.known) {
            // Breadth-first: the cheap test failed; the ray waits for a later region
            ++counters_.deferrals;
            tell(true);
            order_->deferred(task);
            continue;
        }
        ++counters_.rays[int(task.query.kind)];
        const bool primaryHit = task.query.kind == RayKind::Primary && lookup.answer().object >= 0;
        if (primaryHit) ++counters_.primaryHits;
        if (lookup.decision == Decision::Hit) ++counters_.hits;
        if (lookup.decision == Decision::Miss) {
            ++counters_.misses;
            ++counters_.missReasons[int(lookup.reason)];
            // A miss at a parent flushes the entries of its children
            if (order_->flushesChildren()) paths_.flushBelow(task.node);
        }
        // (an uncached answer of the linear scan is the verifier's own: nothing to compare)
        if (options_.verify &&
            (lookup.decision != Decision::Uncached || options_.accel != AccelKind::Linear)) {
            Counters scratch;
            if (!(verifier_.nearest(task.query, scratch) == lookup.answer()))
                ++counters_.verifyDisagreements;
        }
        // Shade: add to the pixel, spawn the children; the cache tree gives each its path
        children_.clear();
        shade(*scene_, task, lookup.answer(), options_.shading, image_, children_);
        for (RayTask& c : children_)
            c.node = paths_.child(task.node, c.query.kind, c.query.light, c.sample);
        // [session-step]
        tell(false);
        order_->committed(task, lookup.decision, children_);
        ++steps_;
        return true;
    }
    done_ = true;
    return false;
}

bool RenderSession::run(const std::function<bool(double)>& progress) {
    std::int64_t n = 0;
    while (step()) {
        if (progress && (++n & 0xFFFF) == 0 && !progress(this->progress())) return false;
    }
    if (progress) progress(1.0);
    return true;
}

SessionCheckpoint RenderSession::checkpoint(const SessionCheckpoint* previous) const {
    SessionCheckpoint c;
    checkpointInto(c, previous);
    return c;
}

void RenderSession::checkpointInto(SessionCheckpoint& c, const SessionCheckpoint* previous) const {
    if (&c == previous) throw std::invalid_argument("checkpointInto: the checkpoint it shares scanlines with");
    c.session = this;
    c.steps = steps_;
    c.primaries = primaries_;
    c.done = done_;
    c.counters = counters_;
    c.paths = paths_;
    c.image = ImageSnapshot(image_, previous ? &previous->image : nullptr);
    // An old clone of the order takes the order's state into the memory it has
    if (c.order && c.order->kind() == order_->kind()) c.order->restore(*order_);
    else c.order = order_->clone();
    c.strategy = strategy_->checkpoint();
}

void RenderSession::restore(const SessionCheckpoint& c) {
    if (c.session != this || !c.order || c.order->kind() != order_->kind())
        throw std::invalid_argument("restore: a checkpoint of another render");
    if (c.steps > steps_) throw std::invalid_argument("restore: the render is not yet at the checkpoint");
    strategy_->restore(c.strategy.get());
    order_->restore(*c.order);
    c.image.restore(image_);
    paths_ = c.paths;
    counters_ = c.counters;
    steps_ = c.steps;
    primaries_ = c.primaries;
    done_ = c.done;
}

}  // namespace rc
