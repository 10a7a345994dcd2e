// The web edition's binding layer: what the viewer page (web/index.html, its worker
// web/render_worker.js) asks of the core, through embind. A render is a SessionState
// stepped ray by ray, as in the Qt GUI, and its overlays are the core's (rc::focusShapes,
// rc::missLayer, rc::regionLayer, rc::focusCaption): nothing here computes an image, an
// answer or an overlay's geometry, it only hands them over.
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "view/image_projector.h"
#include "view/overlay_layers.h"
#include "view/overlay_shapes.h"
#include "view/session_state.h"
#include "view/tour.h"

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

// The built-in scenes, one "name\tdescription" line each
std::string builtinSceneList() {
    std::string out;
    for (const BuiltinInfo& b : builtinScenes()) out += b.name + "\t" + b.description + "\n";
    return out;
}

// The names of the miss reasons, by their number in missReasons(), one a line
std::string missReasonNames() {
    std::string out;
    for (int r = 0; r < kMissReasons; ++r) out += std::string(toString(MissReason(r))) + "\n";
    return out;
}

// A stop of a tour that travels with the page (under /tours), read by the core's parser,
// as JSON: {title, caption, page, stops, settings: [[key, value], ...]}; {error} if it
// cannot be read
std::string tourStop(const std::string& name, int stop) {
    try {
        const Tour tour = loadTour("/tours/" + name + ".json");
        if (stop < 1 || stop > int(tour.stops.size()))
            return nlohmann::json{{"error", tour.file + ": no stop " + std::to_string(stop) + " (it has " +
                                                std::to_string(tour.stops.size()) + ")"}}.dump();
        const TourStop& st = tour.stops[std::size_t(stop - 1)];
        nlohmann::json settings = nlohmann::json::array();
        for (const TourSetting& s : st.settings) settings.push_back({s.key, s.value});
        return nlohmann::json{{"title", st.title}, {"caption", st.caption}, {"page", st.page},
                              {"tour", tour.title}, {"stops", tour.stops.size()}, {"settings", settings}}.dump();
    } catch (const std::exception& e) {
        return nlohmann::json{{"error", e.what()}}.dump();
    }
}

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
    WebRender(const std::string& scene, int width, int height, const std::string& cache, const std::string& order,
              const std::string& accel) {
        SessionConfig config;
        config.scene = std::make_shared<const Scene>(loadScene(scene, 1986));
        RenderOptions& o = config.options;
        o.width = width > 0 ? width : config.scene->camera.width;
        o.height = height > 0 ? height : config.scene->camera.height;
        const auto c = parseCacheKind(cache);
        const auto r = parseOrderKind(order);
        const auto a = parseAccelKind(accel);
        if (!c || !r || !a) throw std::invalid_argument("unknown cache, order or search");
        o.cache = *c;
        o.order = *r;
        o.accel = *a;
        // The page has no Step back: one checkpoint, at step 0
        config.checkpointEvery = std::numeric_limits<std::int64_t>::max() / 2;
        state_ = std::make_unique<SessionState>(std::move(config));
        projector_ = std::make_unique<ImageProjector>(state_->scene().camera, state_->camera());
    }

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
        if (state_->stopEvent() >= 0) selection_.event = state_->stopEvent();
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
        selection_.event = showcaseEvent(*state_);
        return selection_.event >= 0;
    }
    void clearSelection() { selection_ = {}; }
    int selectedPixel() const { return selection_.pixel; }

    /// The 8-bit RGB image, rows top to bottom (a view into memory the next call may move).
    val image() {
        rgb_ = state_->session().image().rgb8();
        return val(emscripten::typed_memory_view(rgb_.size(), rgb_.data()));
    }
    /// Intersection tests made for each pixel so far.
    val heat() {
        const TraceRecorder& rec = state_->recorder();
        heat_.resize(std::size_t(width()) * std::size_t(height()));
        for (std::size_t i = 0; i < heat_.size(); ++i) heat_[i] = std::uint32_t(rec.testsAt(int(i)));
        return val(emscripten::typed_memory_view(heat_.size(), heat_.data()));
    }
    /// The miss markers: each pixel's miss reason at the path of the ray in focus
    /// (rc::missLayer; 0: none; see missReasonNames).
    val missReasons() {
        const auto f = RayFocus::of(*state_, selection_);
        misses_ = missLayer(*state_, f ? f->node : 0);
        return val(emscripten::typed_memory_view(misses_.size(), misses_.data()));
    }
    /// The breadth-first regions (rc::regionLayer: 1 the region being filled, 2 the edge
    /// of a finished one).
    val regions() {
        regions_ = regionLayer(*state_);
        return val(emscripten::typed_memory_view(regions_.size(), regions_.data()));
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
        const auto f = RayFocus::of(*state_, selection_);
        if (!f) return out;
        projector_->setClip({left, top, right, bottom});
        for (const OverlayShape& s : focusShapes(*state_, *f, *projector_, {cylinder, hull})) {
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

    /// The caption of the render and of the ray in focus (rc::focusCaption), a line each.
    std::string caption() const {
        std::string out;
        for (const std::string& line : focusCaption(*state_, selection_)) out += line + "\n";
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
                              {"steps", state_->session().steps()}}
            .dump();
    }

private:
    std::unique_ptr<SessionState> state_;
    std::unique_ptr<ImageProjector> projector_;
    Selection selection_;
    std::vector<std::uint8_t> rgb_, misses_, regions_;
    std::vector<std::uint32_t> heat_;
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
    function("builtinSceneList", &builtinSceneList);
    function("checkScene", &checkScene);
    function("missReasonNames", &missReasonNames);
    function("tourStop", &tourStop);
    class_<WebRender>("Render")
        .constructor<std::string, int, int, std::string, std::string, std::string>()
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
        .function("image", &WebRender::image)
        .function("heat", &WebRender::heat)
        .function("missReasons", &WebRender::missReasons)
        .function("regions", &WebRender::regions)
        .function("frontier", &WebRender::frontier)
        .function("shapes", &WebRender::shapes)
        .function("legend", &WebRender::legend)
        .function("statistics", &WebRender::statistics)
        .function("caption", &WebRender::caption)
        .function("focusPixel", &WebRender::focusPixel);
}
