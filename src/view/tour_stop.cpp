#include "view/tour_stop.h"

#include <algorithm>
#include <sstream>

#include "trace/trace_event.h"
#include "view/overlay_layers.h"
#include "view/overlay_registry.h"

namespace rc {

bool StopPlan::has(const std::string& overlay) const {
    return std::find(overlays.begin(), overlays.end(), overlay) != overlays.end();
}

namespace {

/// The comma-separated words of `text`, trimmed, without empty ones.
std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string w; std::getline(in, w, ',');) {
        const auto first = w.find_first_not_of(" \t"), last = w.find_last_not_of(" \t");
        if (first != std::string::npos) out.push_back(w.substr(first, last - first + 1));
    }
    return out;
}

/// The overlays a stop names, by their registered names; "all" is every one
std::vector<std::string> overlaysOf(const TourStop& st) {
    std::vector<std::string> out;
    auto add = [&out](const std::string& name) {
        if (!name.empty() && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    };
    for (const std::string& w : words(st.value("overlays"))) {
        if (w == "all")
            for (const OverlayInfo& o : overlayRegistry().entries()) add(o.name);
        else
            add(overlayNamed(w));
    }
    return out;
}

/// What only the Qt window shows of the stop, in words
std::vector<std::string> qtOnlyOf(const TourStop& st, const StopPlan& plan) {
    std::vector<std::string> out;
    auto set = [&st](const char* key) {
        return std::any_of(st.settings.begin(), st.settings.end(), [key](const TourSetting& s) { return s.key == key; });
    };
    if (set("scene-view")) out.push_back("the scene view (" + st.value("scene-view", "side") + ")");
    if (set("panels")) {
        // The page shows the ray tree too (rc::rayTreeRows), not the other panels
        std::string panels;
        std::stringstream list(st.value("panels"));
        for (std::string p; std::getline(list, p, ',');)
            if (p != "ray-tree") panels += (panels.empty() ? "" : ",") + p;
        if (!panels.empty()) out.push_back("the panels (" + panels + ")");
    }
    if (!plan.heatmap.empty() && plan.heatmap != "tests") out.push_back("the " + plan.heatmap + " heatmap");
    for (const char* key : {"spp", "light-radius", "shadow-samples", "gloss", "gloss-samples", "orbit", "seed"})
        if (set(key)) out.push_back(std::string("--") + key);
    if (plan.has("samples")) out.push_back("the sample rays");
    if (!plan.run.empty() && plan.run != "next-miss") out.push_back("the run to " + plan.run);
    return out;
}

int intOf(const TourStop& st, const std::string& key, int otherwise) {
    const std::string v = st.value(key);
    return v.empty() ? otherwise : std::stoi(v);
}

}  // namespace

StopPlan planOf(const Tour& tour, int k) {
    if (k < 1 || k > int(tour.stops.size()))
        throw TourError(tour.file, 0, 0, "no stop " + std::to_string(k) + " (it has " + std::to_string(tour.stops.size()) + ")");
    const TourStop& st = tour.stops[std::size_t(k - 1)];
    StopPlan p;
    p.scene = stopScene(tour, st);
    p.width = intOf(st, "width", 0);
    p.height = intOf(st, "height", 0);
    p.cache = st.value("cache", p.cache);
    p.order = st.value("order", p.order);
    p.accel = st.value("accel", p.accel);
    p.band = intOf(st, "band", -1);
    const std::string compare = st.value("compare");
    if (const auto colon = compare.find(':'); colon != std::string::npos) {
        p.compareCache = compare.substr(0, colon);
        p.compareOrder = compare.substr(colon + 1);
    }
    p.overlays = overlaysOf(st);
    p.heatmap = st.value("heatmap");
    if (p.heatmap == "none") p.heatmap.clear();
    p.steps = std::stoll(st.value("steps", "0"));
    p.run = st.value("run");
    p.missReason = st.value("miss-reason");
    if (const std::string s = st.value("select"); !s.empty()) {
        // x,y or x,y:path
        const auto colon = s.find(':');
        const std::vector<std::string> xy = words(s.substr(0, colon));
        if (xy.size() == 2) p.select = StopSelect{std::stoi(xy[0]), std::stoi(xy[1]), colon == std::string::npos ? "" : s.substr(colon + 1)};
    }
    if (const std::vector<std::string> f = words(st.value("focus")); f.size() == 4) {
        std::vector<double> r;
        for (const std::string& v : f) r.push_back(std::stod(v));
        if (r[0] < r[2] && r[1] < r[3]) p.focus = r;
    }
    if (!p.focus) p.zoom = std::stod(st.value("zoom", "0"));
    // The Qt GUI's rule: a scene view with no ray chosen shows a ray worth seeing
    const bool sceneView = std::any_of(st.settings.begin(), st.settings.end(), [](const TourSetting& s) { return s.key == "scene-view"; });
    p.showcase = sceneView && !p.select && p.run.empty();
    p.qtOnly = qtOnlyOf(st, p);
    return p;
}

StopApplied applyStopRays(SessionState& state, const StopPlan& plan) {
    StopApplied out;
    // [stop rays]
    if (plan.steps > 0) state.runUntil(RunGoal::ToStep, plan.steps);
    if (plan.run == "next-miss") {
        MissReason filter = MissReason::None;
        for (int r = 1; r < kMissReasons; ++r)
            if (plan.missReason == toString(MissReason(r))) filter = MissReason(r);
        state.setMissFilter(filter);
        state.runUntil(RunGoal::NextMiss, 0);
        // The miss run to comes in focus, its pixel selected
        if (const int e = state.stopEvent(); e >= 0) {
            out.selection.event = e;
            if (const auto f = RayFocus::ofEvent(state, e)) out.selection.pixel = f->pixel;
        } else {
            out.notes.push_back("no such miss before the end");
        }
    }
    if (plan.showcase) {
        if (const int e = showcaseEvent(state); e >= 0) {
            out.selection = {};
            out.selection.event = e;
            if (const auto f = RayFocus::ofEvent(state, e)) out.selection.pixel = f->pixel;
        }
    }
    if (plan.select) {
        const StopSelect& s = *plan.select;
        if (s.x < 0 || s.y < 0 || s.x >= state.width() || s.y >= state.height()) {
            out.notes.push_back("select: pixel (" + std::to_string(s.x) + "," + std::to_string(s.y) + ") is outside the " +
                                std::to_string(state.width()) + "x" + std::to_string(state.height()) + " image");
            return out;
        }
        out.selection = {};
        out.selection.pixel = s.y * state.width() + s.x;
        if (!s.path.empty()) {
            std::string why;
            out.selection.event = eventAtPath(state, out.selection.pixel, s.path, why);
            if (out.selection.event < 0) out.notes.push_back("select: " + why);
        }
    }
    // [stop rays]
    return out;
}

}  // namespace rc
