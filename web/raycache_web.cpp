// The web edition's binding layer: what the viewer page (web/index.html, its worker
// web/render_worker.js) asks of the core, through embind. A render is a SessionState
// stepped ray by ray, as in the Qt GUI, and its overlays are the core's (rc::focusShapes,
// rc::missLayer, rc::regionLayer, rc::focusCaption): nothing here computes an image, an
// answer or an overlay's geometry, it only hands them over.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include "render/left_out.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"
#include "view/image_projector.h"
#include "view/overlay_layers.h"
#include "view/overlay_shapes.h"
#include "view/session_state.h"
#include "view/compare_caption.h"
#include "view/legend.h"
#include "view/palette.h"
#include "view/ray_tree_rows.h"
#include "view/registry_listing.h"
#include "view/scene_list.h"
#include "view/tour.h"
#include "view/tour_stop.h"
#include "view/claim.h"
#include "view/heatmap.h"

namespace {

using namespace rc;
using emscripten::val;

// Stores a dropped NFF file in the page's in-memory file system, so that loadScene()
// reads it as it reads any file (errors name it: dropped.nff:line:column)
std::string storeSceneFile(const std::string& name, const std::string& text) {
    const std::string path = "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// The Scene menu (rc::sceneChoices, as the Qt GUI's): the built-ins, then the SPD scenes the
// page carries under /scenes, as JSON [{spec, label, description, file}]
std::string sceneList() {
    nlohmann::json out = nlohmann::json::array();
    for (const SceneChoice& c : sceneChoices("/scenes"))
        out.push_back({{"spec", c.spec}, {"label", c.label}, {"description", c.description}, {"file", c.file}});
    return out.dump();
}

// The names of the miss reasons, by their number in missReasons(), one a line
std::string missReasonNames() {
    std::string out;
    for (int r = 0; r < kMissReasons; ++r) out += std::string(toString(MissReason(r))) + "\n";
    return out;
}

// A tour that travels with the page (under /tours)
Tour pageTour(const std::string& name) { return loadTour("/tours/" + name + ".json"); }

// A stop of a tour that travels with the page, as the core reads and plans it (rc::planOf),
// as JSON: {title, caption, page, tour, stops, plan: {scene, width, ..., qtOnly}}; {error}
// if it cannot be read
std::string tourStop(const std::string& name, int stop) {
    try {
        const Tour tour = pageTour(name);
        const StopPlan p = planOf(tour, stop);
        const TourStop& st = tour.stops[std::size_t(stop - 1)];
        nlohmann::json plan = {{"scene", p.scene},       {"width", p.width},     {"height", p.height},
                               {"cache", p.cache},       {"order", p.order},     {"accel", p.accel},
                               {"band", p.band},         {"overlays", p.overlays}, {"heatmap", p.heatmap},
                               {"compare", p.compareCache.empty() ? "" : p.compareCache + ":" + p.compareOrder},
                               {"zoom", p.zoom},         {"qtOnly", p.qtOnly}};
        plan["focus"] = p.focus ? nlohmann::json(*p.focus) : nlohmann::json();
        return nlohmann::json{{"title", st.title}, {"caption", st.caption}, {"page", st.page},
                              {"tour", tour.title}, {"stops", tour.stops.size()}, {"plan", plan}}.dump();
    } catch (const std::exception& e) {
        return nlohmann::json{{"error", e.what()}}.dump();
    }
}

// What a registry holds (rc::registryListing), as JSON: the page's menus; {error} when
// `what` names no registry
std::string registry(const std::string& what) {
    try {
        return registryListing(what).dump();
    } catch (const std::exception& e) {
        return nlohmann::json{{"error", e.what()}}.dump();
    }
}

// The viewer's colours and role styles (rc::roleStyle, rc::missReasonColour, rc::heatRamp,
// rc::colours), as JSON: the page draws with the Qt GUI's numbers, read from the one place
std::string palette() {
    const auto rgb = [](Rgb c) { return nlohmann::json::array({c.r, c.g, c.b}); };
    nlohmann::json roles = nlohmann::json::object();
    for (int r = 0; r < kShapeRoles; ++r) {
        const RoleStyle st = roleStyle(ShapeRole(r));
        roles[toString(ShapeRole(r))] = {{"colour", rgb(st.colour)}, {"width", st.width}, {"dash", st.dashed},
                                         {"fill", st.fill},          {"star", st.star},   {"arms", st.arms}};
    }
    nlohmann::json misses = nlohmann::json::array();
    for (int r = 0; r < kMissReasons; ++r) misses.push_back(r == 0 ? nlohmann::json() : rgb(missReasonColour(MissReason(r))));
    constexpr int kRampSteps = 1024;
    nlohmann::json ramp = nlohmann::json::array();
    for (int i = 0; i < kRampSteps; ++i) ramp.push_back(rgb(heatRamp(double(i) / (kRampSteps - 1))));
    using namespace colours;
    return nlohmann::json{{"roles", roles}, {"misses", misses}, {"ramp", ramp},
                          {"colours", {{"ray", rgb(kRay)}, {"cylinder", rgb(kCylinder)}, {"hull", rgb(kHull)},
                                       {"target", rgb(kTarget)}, {"blocker", rgb(kBlocker)}, {"queued", rgb(kQueued)},
                                       {"deferred", rgb(kDeferred)}, {"region", rgb(kRegion)},
                                       {"regionEdge", rgb(kRegionEdge)}, {"selection", rgb(kSelection)},
                                       {"missCause", rgb(kMissCause)}, {"missText", rgb(kMissText)},
                                       {"deferredText", rgb(kDeferredText)}}}}
        .dump();
}

// "unknown cache 'bogus': choose none, cylinder, ...": a name no registry entry has
template <class Kind>
Kind named(const std::optional<Kind>& kind, const char* what, const std::string& name, const nlohmann::json& list) {
    if (kind) return *kind;
    std::string choices;
    for (const auto& e : list) choices += (choices.empty() ? "" : ", ") + e["name"].get<std::string>();
    throw std::invalid_argument(std::string("unknown ") + what + " '" + name + "': choose " + choices);
}

// The largest width or height the page traces (viewer.js's inputs say the same)
constexpr int kMaxWebSize = 2048;

val points(const Outline& outline) {
    val out = val::array();
    for (const ImagePoint& p : outline) {
        out.call<void>("push", p.x);
        out.call<void>("push", p.y);
    }
    return out;
}

class WebRender {
public:
    /// Never throws: a scene or a choice that cannot be used leaves error() saying why (a
    /// C++ exception reaches JavaScript as a bare number, not as its message).
    WebRender(const std::string& scene, int width, int height, const std::string& cache, const std::string& order,
              const std::string& accel, int band) {
        try {
            open(scene, width, height, cache, order, accel, band);
        } catch (const std::bad_alloc&) {
            error_ = "out of memory: the image is too large for this tab";
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    /// Why the render could not be made ("" when it was).
    std::string error() const { return error_; }

private:
    void open(const std::string& scene, int width, int height, const std::string& cache, const std::string& order,
              const std::string& accel, int band) {
        SessionConfig config;
        config.scene = std::make_shared<const Scene>(loadScene(scene, 1986));
        RenderOptions& o = config.options;
        o.width = width > 0 ? width : config.scene->camera.width;
        o.height = height > 0 ? height : config.scene->camera.height;
        // A tab holds about 4 GB: the page keeps its images up to kMaxWebSize on a side
        if (o.width > kMaxWebSize || o.height > kMaxWebSize)
            throw std::invalid_argument("the page traces images of at most " + std::to_string(kMaxWebSize) + "x" +
                                        std::to_string(kMaxWebSize) + " pixels, not " + std::to_string(o.width) +
                                        "x" + std::to_string(o.height) +
                                        " (larger ones need more memory than a browser tab has; raycache render "
                                        "traces up to " + std::to_string(NffLimits::maxResolution) + ")");
        o.cache = named(parseCacheKind(cache), "cache", cache, registryListing("caches"));
        o.order = named(parseOrderKind(order), "order", order, registryListing("orders"));
        o.accel = named(parseAccelKind(accel), "search", accel, registryListing("searches"));
        if (band > NffLimits::maxResolution) throw std::invalid_argument("band " + std::to_string(band) + " is too large");
        o.band = band < 0 ? kAutoBand : band;
        // Its memory keeps all it is given: the order's paths take room as they fill
        o.reserveRays = false;
        // The page has no Step back: one checkpoint, at step 0
        config.checkpointEvery = std::numeric_limits<std::int64_t>::max() / 2;
        // and shows of the per-pixel tallies only the tests heatmap and which pixels were traced
        config.keepTallies = false;
        state_ = std::make_unique<SessionState>(std::move(config));
        projector_ = std::make_unique<ImageProjector>(state_->scene().camera, state_->camera());
    }

public:

    int width() const { return state_->width(); }
    int height() const { return state_->height(); }
    bool done() const { return state_->session().done(); }
    double progress() const { return state_->session().progress(); }
    double steps() const { return double(state_->session().steps()); }

    /// Traces up to `n` rays; returns false when the image is complete. The ray being
    /// traced comes back in focus.
    bool run(int n) {
        selection_ = {};
        for (int i = 0; i < n; ++i)
            if (!state_->step()) return false;
        return !done();
    }
    /// Traces rays until step `target` (a tour stop's "steps").
    void runToStep(double target) {
        selection_ = {};
        state_->runUntil(RunGoal::ToStep, std::int64_t(target));
    }
    /// Traces rays until one of another pixel ("pixel"), or until a committed cache miss
    /// ("miss", of reason `reason` when it names one), which comes in focus. True when
    /// it got there before the end.
    bool runUntil(const std::string& goal, const std::string& reason) {
        selection_ = {};
        MissReason filter = MissReason::None;
        for (int r = 1; r < kMissReasons; ++r)
            if (reason == toString(MissReason(r))) filter = MissReason(r);
        state_->setMissFilter(filter);
        const bool met = state_->runUntil(goal == "miss" ? RunGoal::NextMiss : RunGoal::NextPixel, 0);
        if (state_->stopEvent() >= 0) selectEvent(state_->stopEvent());
        return met && !(goal == "miss" && state_->stopEvent() < 0);
    }
    /// Puts pixel (x, y)'s ray at `path` in focus (its eye ray when `path` is empty);
    /// returns why not, or "".
    std::string select(int x, int y, const std::string& path) {
        if (x < 0 || y < 0 || x >= width() || y >= height())
            return "pixel (" + std::to_string(x) + "," + std::to_string(y) + ") is outside the " +
                   std::to_string(width()) + "x" + std::to_string(height()) + " image";
        selection_ = {};
        selection_.pixel = y * width() + x;
        if (path.empty()) return "";
        std::string why;
        selection_.event = eventAtPath(*state_, selection_.pixel, path, why);
        return why;
    }
    /// Puts a ray worth showing in focus (rc::showcaseEvent), as the Qt GUI does for a
    /// stop that shows the scene view without choosing a ray. False when none is traced.
    bool showcase() {
        selection_ = {};
        const int e = showcaseEvent(*state_);
        if (e >= 0) selectEvent(e);
        return e >= 0;
    }
    void clearSelection() { selection_ = {}; }
    /// Puts event `e` in focus and selects its pixel, as the Qt GUI does for a stop's ray.
    void selectEvent(int e) {
        selection_.event = e;
        if (const auto f = RayFocus::ofEvent(*state_, e)) selection_.pixel = f->pixel;
    }
    int selectedPixel() const { return selection_.pixel; }

    /// The 8-bit RGB image's rows [row, row + rows), top to bottom, for its hash once the
    /// render is complete (a view into memory the next call overwrites): the page asks for
    /// it a band at a time, so neither it nor the WebAssembly memory holds a second
    /// image-sized buffer beside the render's sums.
    val imageRows(int row, int rows) {
        const auto [begin, end] = pixelsOf(row, rows);
        frame_.resize(std::size_t(end - begin) * 3);
        state_->session().image().rgb8Into(frame_.data(), 3, begin, end);
        return val(emscripten::typed_memory_view(frame_.size(), frame_.data()));
    }
    /// The top of this render's tests heatmap (rc::testsTop); two renders side by side
    /// share the larger.
    double heatTop() const { return testsTop(state_->recorder()); }

    /// Begins the picture the page draws at image size, 8-bit RGBA, which pictureRows()
    /// gives a band at a time: the image, or the tests heatmap up to `top`
    /// (rc::testsHeatmapRgbaInto); then the fill's regions (rc::regionLayer: the one being
    /// filled tinted, finished ones edged) and the misses at the path in focus
    /// (rc::missLayer), by reason.
    void beginPicture(bool heatmap, double top, bool misses, bool regions) {
        picture_ = {heatmap, top, {}, {}};
        if (regions) picture_.regions = regionLayer(*state_);
        if (misses) {
            const auto f = RayFocus::of(*state_, selection_);
            picture_.misses = missLayer(*state_, f ? f->node : 0);
        }
    }
    /// Rows [row, row + rows) of the picture beginPicture() began (a view into memory the
    /// next call overwrites).
    val pictureRows(int row, int rows) {
        const std::pair<int, int> pixels = pixelsOf(row, rows);
        const int begin = pixels.first, end = pixels.second;
        frame_.resize(std::size_t(end - begin) * 4);
        if (picture_.heatmap) {
            testsHeatmapRgbaInto(state_->recorder(), picture_.top, frame_.data(), begin, end);
        } else {
            // Straight from the render's sums into the picture, with no RGB copy between
            std::fill(frame_.begin(), frame_.end(), 255);
            state_->session().image().rgb8Into(frame_.data(), 4, begin, end);
        }
        const auto blend = [this, begin](int px, Rgb c, double a) {
            std::uint8_t* d = &frame_[std::size_t(px - begin) * 4];
            const std::uint8_t to[3] = {c.r, c.g, c.b};
            for (int k = 0; k < 3; ++k) d[k] = std::uint8_t(std::lround(d[k] + (to[k] - d[k]) * a));
        };
        const std::vector<std::uint8_t>& r = picture_.regions;
        for (int i = begin; i < end && !r.empty(); ++i) {
            if (r[std::size_t(i)] == 1) blend(i, colours::kRegion, colours::kRegionOpacity / 255.0);
            else if (r[std::size_t(i)] == 2) blend(i, colours::kRegionEdge, colours::kRegionEdgeOpacity / 255.0);
        }
        const std::vector<std::uint8_t>& m = picture_.misses;
        for (int i = begin; i < end && !m.empty(); ++i)
            if (m[std::size_t(i)]) blend(i, missReasonColour(MissReason(m[std::size_t(i)])), 1.0);
        return val(emscripten::typed_memory_view(frame_.size(), frame_.data()));
    }
    /// Ends the picture: its layers are let go.
    void endPicture() { picture_ = {}; }

    /// Applies stop `stop` of tour `tour` (under /tours) to this render, freshly opened with
    /// the stop's settings (rc::applyStopRays): its steps, its run to a miss, its selection.
    /// As JSON: {notes: [...], selected: {x, y, path} or null (the pixel and path chosen by
    /// the stop's select, which a compared render selects too)}.
    std::string applyStop(const std::string& tour, int stop) {
        try {
            const StopPlan plan = planOf(pageTour(tour), stop);
            const StopApplied applied = applyStopRays(*state_, plan);
            selection_ = applied.selection;
            nlohmann::json selected;
            if (plan.select && applied.notes.empty())
                selected = {{"x", plan.select->x}, {"y", plan.select->y}, {"path", plan.select->path}};
            return nlohmann::json{{"notes", applied.notes}, {"selected", selected}}.dump();
        } catch (const std::exception& e) {
            return nlohmann::json{{"notes", {std::string("the stop: ") + e.what()}}, {"selected", nullptr}}.dump();
        }
    }

    /// The claims of stop `stop` of tour `tour` checked on what this render (and `right`, when
    /// the stop compares) draws, by the core's claim evaluation (rc::checkClaim) and its
    /// caption checked for what the stop does not draw (rc::captionSlips). `claims` (JSON,
    /// an array of texts) replaces the stop's own when not empty. As JSON: {results: [{text,
    /// holds, reading}], slips: [...], error}.
    std::string claims(const std::string& tour, int stop, const std::string& claims) const {
        return claimsOf(tour, stop, claims, nullptr);
    }
    std::string claimsCompared(const std::string& tour, int stop, const std::string& claims, const WebRender& right) const {
        return claimsOf(tour, stop, claims, &right);
    }

    /// The fill's queued pixels and deferred seeds, its path and region.
    val frontier() const {
        const FrontierView f = state_->session().order().frontier();
        val out = val::object();
        val queued = val::array(), deferred = val::array();
        for (int px : f.queued) queued.call<void>("push", px);
        for (int px : f.deferred) deferred.call<void>("push", px);
        out.set("queued", queued);
        out.set("deferred", deferred);
        out.set("path", f.path >= 0 ? state_->session().cacheTree().label(f.path) : std::string());
        out.set("region", double(f.region));
        return out;
    }

    /// The overlays of the ray in focus (rc::focusShapes), clipped to the rectangle
    /// (image coordinates) the page shows: [{role, label, outline: [x, y, ...], covers,
    /// flat, segment: [ax, ay, bx, by], point: [x, y]}], in drawing order.
    val shapes(bool cylinder, bool hull, double left, double top, double right, double bottom) {
        val out = val::array();
        drawn_.clear();
        const auto f = RayFocus::of(*state_, selection_);
        if (!f) return out;
        projector_->setClip({left, top, right, bottom});
        drawn_ = focusShapes(*state_, *f, *projector_, {cylinder, hull});
        for (const OverlayShape& s : drawn_) {
            val v = val::object();
            v.set("role", std::string(toString(s.role)));
            v.set("label", s.label);
            v.set("covers", s.covers);
            v.set("flat", s.flat);
            v.set("outline", points(s.outline));
            if (s.segment) v.set("segment", points({s.segment->a, s.segment->b}));
            if (s.point) v.set("point", points({*s.point}));
            out.call<void>("push", v);
        }
        return out;
    }

    /// What the key says besides colours: the hull's listed and drawn blockers, the miss
    /// cause of the ray in focus in words, its pixel and path, the miss counts by reason.
    val legend() const {
        val out = val::object();
        const auto f = RayFocus::of(*state_, selection_);
        out.set("blockerLists", state_->session().strategy().blockerLists() != nullptr);
        if (f) {
            const FocusHull h = hullOf(*state_, *f);
            out.set("blockersShown", double(h.blockers.size()));
            out.set("blockersListed", double(h.listed));
            out.set("cause", missCauseText(*state_, *f));
            out.set("pixel", f->pixel);
            out.set("path", state_->session().cacheTree().label(f->node));
            out.set("selected", f->selected);
        }
        val misses = val::array();
        for (std::uint64_t n : state_->session().counters().missReasons) misses.call<void>("push", double(n));
        out.set("misses", misses);
        return out;
    }

    /// The ray tree of the pixel in focus (rc::rayTreeRows), as JSON: {pixel: [x, y] or null,
    /// rows: [{depth, path, hit, decision, tests, deferred, miss, focus}]} (focus: the ray in focus).
    std::string rayTree() const {
        const auto f = RayFocus::of(*state_, selection_);
        nlohmann::json rows = nlohmann::json::array();
        if (!f) return nlohmann::json{{"pixel", nullptr}, {"rows", rows}}.dump();
        for (const RayTreeRow& r : rayTreeRows(*state_, f->pixel))
            rows.push_back({{"depth", r.depth}, {"path", r.path}, {"hit", r.hit},
                            {"decision", r.decision}, {"tests", r.tests}, {"deferred", r.deferred}, {"miss", r.miss},
                            {"focus", r.event == f->event}});
        return nlohmann::json{{"pixel", {f->pixel % width(), f->pixel / width()}}, {"rows", rows}}.dump();
    }

    /// The key (rc::legendEntries, then rc::focusEntries), for the overlays shown and the
    /// shapes the last shapes() gave (none when neither cylinder nor hull is on), as JSON:
    /// [{colour: [r, g, b] or null, text}].
    std::string keys(bool cylinder, bool hull, bool frontier, bool misses) {
        if (!(cylinder || hull)) drawn_.clear();
        const LegendShown shown{cylinder, hull, frontier, misses};
        nlohmann::json out = nlohmann::json::array();
        for (const auto& entries : {legendEntries(*state_, selection_, shown, drawn_),
                                    focusEntries(*state_, selection_, shown, drawn_)})
            for (const LegendEntry& e : entries)
                out.push_back({{"colour", e.colour ? nlohmann::json::array({e.colour->r, e.colour->g, e.colour->b})
                                                   : nlohmann::json()},
                               {"text", e.text}});
        return out.dump();
    }

    /// The caption of the render and of the ray in focus (rc::focusCaption), a line each.
    std::string caption() const {
        std::string out;
        for (const std::string& line : focusCaption(*state_, selection_)) out += line + "\n";
        return out;
    }
    /// The reader's warnings (rc::Scene::skipped): a polygon of zero area each, as
    /// `file:line:column: message`, one a line.
    std::string warnings() const {
        std::string out;
        for (const std::string& line : state_->scene().skipped) out += line + "\n";
        return out;
    }
    /// The caption of `right` compared with this render (rc::compareCaption), a line each.
    std::string compareCaption(const WebRender& right) const {
        std::string out;
        for (const std::string& line : rc::compareCaption(*state_, *right.state_)) out += line + "\n";
        return out;
    }
    /// The pixel of the ray being traced (-1: none yet).
    int focusPixel() const {
        const auto& e = state_->recorder().lastEvent();
        return e ? e->task.pixel : -1;
    }

    /// The counters, as JSON.
    std::string statistics() const {
        const Counters& n = state_->session().counters();
        return nlohmann::json{{"rays", n.totalRays()},
                              {"primary", n.rays[int(RayKind::Primary)]},
                              {"shadow", n.rays[int(RayKind::Shadow)]},
                              {"reflection", n.rays[int(RayKind::Reflection)]},
                              {"refraction", n.rays[int(RayKind::Refraction)]},
                              {"tests", n.intersectionTests},
                              {"searches", n.completeSearches},
                              {"hits", n.hits},
                              {"misses", n.misses},
                              {"steps", state_->session().steps()},
                              // What the render leaves out (rc::leftOut), polygons of zero area included
                              {"leftOut", leftOut(state_->scene(), &state_->session().options())}}
            .dump();
    }

private:
    std::string claimsOf(const std::string& tourName, int stop, const std::string& replaced, const WebRender* right) const {
        try {
            Tour tour = pageTour(tourName);
            (void)planOf(tour, stop);  // the stop exists
            TourStop& st = tour.stops[std::size_t(stop - 1)];
            const nlohmann::json given = nlohmann::json::parse(replaced.empty() ? "[]" : replaced);
            if (!given.empty()) st.claims = given.get<std::vector<std::string>>();
            std::vector<Claim> parsed;
            if (const std::string error = parseStopClaims(st, parsed); !error.empty())
                return nlohmann::json{{"error", error}}.dump();
            ClaimView view = claimViewOf(st);
            view.panes.push_back({state_.get(), selection_});
            if (right) view.panes.push_back({right->state_.get(), right->selection_});
            nlohmann::json results = nlohmann::json::array();
            for (const Claim& c : parsed) {
                const ClaimResult r = checkClaim(c, view);
                results.push_back({{"text", r.text}, {"holds", r.holds}, {"reading", r.reading}});
            }
            return nlohmann::json{{"results", results}, {"slips", captionSlips(st.caption, parsed, view)}}.dump();
        } catch (const std::exception& e) {
            return nlohmann::json{{"error", e.what()}}.dump();
        }
    }

    std::unique_ptr<SessionState> state_;
    std::unique_ptr<ImageProjector> projector_;
    Selection selection_;
    /// The pixels [begin, end) of rows [row, row + rows), clamped to the image.
    std::pair<int, int> pixelsOf(int row, int rows) const {
        const int top = std::clamp(row, 0, height()), bottom = std::clamp(row + std::max(rows, 0), top, height());
        return {top * width(), bottom * width()};
    }

    /// What beginPicture() was asked for, and its overlays' layers (a byte a pixel, empty
    /// when not shown)
    struct Picture {
        bool heatmap = false;
        double top = 1;
        std::vector<std::uint8_t> regions, misses;
    };
    Picture picture_;
    std::vector<std::uint8_t> frame_;  ///< pictureRows() and imageRows() write here: one band
    std::string error_;
    std::vector<OverlayShape> drawn_;  ///< the shapes the last shapes() gave
};

// Scene errors reach the page as text (file:line:column: message), not as an abort
std::string checkScene(const std::string& scene) {
    try {
        (void)loadScene(scene, 1986);
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

}  // namespace

EMSCRIPTEN_BINDINGS(raycache) {
    using namespace emscripten;
    function("storeSceneFile", &storeSceneFile);
    function("sceneList", &sceneList);
    function("checkScene", &checkScene);
    function("missReasonNames", &missReasonNames);
    function("tourStop", &tourStop);
    function("registry", &registry);
    function("palette", &palette);
    constant("maxSize", kMaxWebSize);
    class_<WebRender>("Render")
        .constructor<std::string, int, int, std::string, std::string, std::string, int>()
        .function("error", &WebRender::error)
        .function("width", &WebRender::width)
        .function("height", &WebRender::height)
        .function("done", &WebRender::done)
        .function("progress", &WebRender::progress)
        .function("steps", &WebRender::steps)
        .function("run", &WebRender::run)
        .function("runToStep", &WebRender::runToStep)
        .function("runUntil", &WebRender::runUntil)
        .function("select", &WebRender::select)
        .function("showcase", &WebRender::showcase)
        .function("clearSelection", &WebRender::clearSelection)
        .function("selectedPixel", &WebRender::selectedPixel)
        .function("imageRows", &WebRender::imageRows)
        .function("heatTop", &WebRender::heatTop)
        .function("beginPicture", &WebRender::beginPicture)
        .function("pictureRows", &WebRender::pictureRows)
        .function("endPicture", &WebRender::endPicture)
        .function("applyStop", &WebRender::applyStop)
        .function("claims", &WebRender::claims)
        .function("claimsCompared", &WebRender::claimsCompared)
        .function("frontier", &WebRender::frontier)
        .function("shapes", &WebRender::shapes)
        .function("legend", &WebRender::legend)
        .function("keys", &WebRender::keys)
        .function("compareCaption", &WebRender::compareCaption)
        .function("rayTree", &WebRender::rayTree)
        .function("statistics", &WebRender::statistics)
        .function("caption", &WebRender::caption)
        .function("warnings", &WebRender::warnings)
        .function("focusPixel", &WebRender::focusPixel);
}
