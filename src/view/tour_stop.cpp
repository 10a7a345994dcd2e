#include "view/tour_stop.h"

#include <algorithm>

#include "trace/trace_event.h"
#include "view/overlay_layers.h"

namespace rc {

bool StopPlan::has(const std::string& overlay) const {
    return std::find(overlays.begin(), overlays.end(), overlay) != overlays.end();
}

namespace {

/// What only the Qt window shows of the stop, in words
std::vector<std::string> qtOnlyOf(const TourStop& st, const ViewerSettings& v, const StopPlan& plan) {
    std::vector<std::string> out;
    auto set = [&st](const char* key) {
        return std::any_of(st.settings.begin(), st.settings.end(), [key](const TourSetting& s) { return s.key == key; });
    };
    if (!v.sceneView.empty()) out.push_back("the scene view (" + v.sceneView + ")");
    if (v.panels) {
        // The page shows the ray tree too (rc::rayTreeRows), not the other panels
        std::string panels;
        for (const std::string& p : *v.panels)
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

}  // namespace

StopPlan planOf(const Tour& tour, int k) {
    // The one reader: the Qt window reads its stops with it too
    const ViewerSettings v = stopSettings(tour, k);
    const TourStop& st = tour.stops[std::size_t(k - 1)];
    StopPlan p;
    p.scene = v.scene;
    p.width = v.width;
    p.height = v.height;
    p.cache = v.cache;
    p.order = v.order;
    p.accel = v.accel;
    p.band = v.band;
    p.compareCache = v.compareCache;
    p.compareOrder = v.compareOrder;
    p.overlays = v.overlays.value_or(std::vector<std::string>{});
    p.heatmap = v.heatmap;
    p.steps = std::max<std::int64_t>(0, v.steps);
    p.run = v.run;
    p.missReason = v.missReason;
    p.select = v.select;
    if (v.focus) p.focus = std::vector<double>(v.focus->begin(), v.focus->end());
    else p.zoom = v.zoom.value_or(0);
    // The Qt GUI's rule: a scene view with no ray chosen shows a ray worth seeing
    p.showcase = !v.sceneView.empty() && !p.select && p.run.empty();
    p.qtOnly = qtOnlyOf(st, v, p);
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
