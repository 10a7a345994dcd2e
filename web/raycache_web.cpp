// The web edition's binding layer: what the viewer page (web/index.html, its worker
// web/render_worker.js) asks of the core, through embind. A render is a RenderSession
// stepped ray by ray, as in the Qt GUI; nothing here computes an image or an answer.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"

namespace {

using namespace rc;

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

// The last ray traced; for each pixel the intersection tests made (the heatmap) and the
// reason of its last committed cache miss (the miss markers; 0: none)
class StepRecorder : public TraceSink {
public:
    explicit StepRecorder(int pixels) : tests(std::size_t(pixels), 0), missReason(std::size_t(pixels), 0) {}
    void onEvent(const TraceEvent& e) override {
        last = e;
        any = true;
        tests[std::size_t(e.task.pixel)] += std::uint32_t(e.tests);
        if (!e.deferred && e.lookup.decision == Decision::Miss)
            missReason[std::size_t(e.task.pixel)] = std::uint8_t(e.lookup.reason);
    }
    TraceEvent last;
    bool any = false;
    std::vector<std::uint32_t> tests;
    std::vector<std::uint8_t> missReason;
};

// The names of the miss reasons, by their number in missReasons(), one a line
std::string missReasonNames() {
    std::string out;
    for (int r = 0; r < kMissReasons; ++r) out += std::string(toString(MissReason(r))) + "\n";
    return out;
}

class WebRender {
public:
    WebRender(const std::string& scene, int width, int height, const std::string& cache, const std::string& order,
              const std::string& accel) {
        auto s = std::make_shared<const Scene>(loadScene(scene, 1986));
        RenderOptions o;
        o.width = width > 0 ? width : s->camera.width;
        o.height = height > 0 ? height : s->camera.height;
        const auto c = parseCacheKind(cache);
        const auto r = parseOrderKind(order);
        const auto a = parseAccelKind(accel);
        if (!c || !r || !a) throw std::invalid_argument("unknown cache, order or search");
        o.cache = *c;
        o.order = *r;
        o.accel = *a;
        session_ = std::make_unique<RenderSession>(s, o);
        recorder_ = std::make_unique<StepRecorder>(o.width * o.height);
        session_->addSink(recorder_.get());
    }

    int width() const { return session_->width(); }
    int height() const { return session_->height(); }
    bool done() const { return session_->done(); }
    double progress() const { return session_->progress(); }
    double steps() const { return double(session_->steps()); }

    /// Traces up to `n` rays; returns false when the image is complete.
    bool run(int n) {
        for (int i = 0; i < n; ++i)
            if (!session_->step()) return false;
        return !session_->done();
    }
    /// Traces rays until one of another pixel than the last traced has been traced, or
    /// until a committed cache miss ("miss"), at most `limit` rays. True when it got there.
    bool runUntil(const std::string& goal, int limit) {
        const int pixel = recorder_->any ? recorder_->last.task.pixel : -1;
        for (int i = 0; i < limit; ++i) {
            if (!session_->step()) return false;
            const TraceEvent& e = recorder_->last;
            if (goal == "pixel" && e.task.pixel != pixel) return true;
            if (goal == "miss" && !e.deferred && e.lookup.decision == Decision::Miss) return true;
        }
        return false;
    }

    /// The 8-bit RGB image, rows top to bottom (a view into memory the next call may move).
    emscripten::val image() {
        rgb_ = session_->image().rgb8();
        return emscripten::val(emscripten::typed_memory_view(rgb_.size(), rgb_.data()));
    }
    /// Intersection tests made for each pixel so far.
    emscripten::val heat() const {
        return emscripten::val(emscripten::typed_memory_view(recorder_->tests.size(), recorder_->tests.data()));
    }

    /// The reason of each pixel's last committed cache miss (0: none; see missReasonNames).
    emscripten::val missReasons() const {
        return emscripten::val(
            emscripten::typed_memory_view(recorder_->missReason.size(), recorder_->missReason.data()));
    }

    /// The counters, as JSON.
    std::string statistics() const {
        const Counters& n = session_->counters();
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "{\"rays\":%llu,\"primary\":%llu,\"shadow\":%llu,\"reflection\":%llu,\"refraction\":%llu,"
                      "\"tests\":%llu,\"searches\":%llu,\"hits\":%llu,\"misses\":%llu,\"steps\":%lld}",
                      (unsigned long long)n.totalRays(), (unsigned long long)n.rays[int(RayKind::Primary)],
                      (unsigned long long)n.rays[int(RayKind::Shadow)],
                      (unsigned long long)n.rays[int(RayKind::Reflection)],
                      (unsigned long long)n.rays[int(RayKind::Refraction)], (unsigned long long)n.intersectionTests,
                      (unsigned long long)n.completeSearches, (unsigned long long)n.hits,
                      (unsigned long long)n.misses, (long long)session_->steps());
        return buf;
    }

    /// The ray in focus (the last traced), in words; its pixel is focusPixel().
    std::string caption() const {
        if (!recorder_->any) return "no ray traced yet";
        const TraceEvent& e = recorder_->last;
        const int w = session_->width();
        std::string c = "ray " + std::to_string(e.step + 1) + ": pixel (" + std::to_string(e.task.pixel % w) + ", " +
                        std::to_string(e.task.pixel / w) + "), " + std::string(toString(e.task.query.kind)) +
                        " ray, depth " + std::to_string(e.task.depth) + ", ";
        if (e.deferred) c += "deferred, ";
        c += std::string(toString(e.lookup.decision));
        if (e.lookup.reason != MissReason::None) c += " (" + std::string(toString(e.lookup.reason)) + ")";
        c += e.lookup.object < 0 ? ", hits nothing" : ", hits object #" + std::to_string(e.lookup.object);
        c += ", " + std::to_string(e.tests) + " intersection tests";
        if (e.lookup.searched) c += ", complete search";
        return c;
    }
    int focusPixel() const { return recorder_->any ? recorder_->last.task.pixel : -1; }

private:
    std::unique_ptr<RenderSession> session_;
    std::unique_ptr<StepRecorder> recorder_;
    std::vector<std::uint8_t> rgb_;
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
    class_<WebRender>("Render")
        .constructor<std::string, int, int, std::string, std::string, std::string>()
        .function("width", &WebRender::width)
        .function("height", &WebRender::height)
        .function("done", &WebRender::done)
        .function("progress", &WebRender::progress)
        .function("steps", &WebRender::steps)
        .function("run", &WebRender::run)
        .function("runUntil", &WebRender::runUntil)
        .function("image", &WebRender::image)
        .function("heat", &WebRender::heat)
        .function("missReasons", &WebRender::missReasons)
        .function("statistics", &WebRender::statistics)
        .function("caption", &WebRender::caption)
        .function("focusPixel", &WebRender::focusPixel);
}
