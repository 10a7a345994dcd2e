#include "heatmap_builder.h"

#include <algorithm>
#include <cmath>

#include "palette.h"
#include "session_controller.h"
#include "view/heatmap.h"

namespace rcgui {

double HeatmapBuilder::scaleOf(const rc::SessionState& s, Heatmap mode) {
    if (mode == Heatmap::VisitOrder) return std::max<double>(1.0, double(s.session().steps()));
    if (mode == Heatmap::HitRate) return 1.0;
    if (mode != Heatmap::Tests) return 0.0;
    return rc::testsTop(s.recorder());
}

std::optional<double> HeatmapBuilder::hitRate(const rc::SessionState& s, int px) {
    const double hits = s.recorder().hitsAt(px), misses = s.recorder().missesAt(px);
    if (hits + misses == 0) return std::nullopt;
    return hits / (hits + misses);
}

QImage HeatmapBuilder::build(const rc::SessionState& s, Heatmap mode, int path, double top) {
    if (mode == Heatmap::None) return SessionController::imageOf(s);
    const rc::TraceRecorder& rec = s.recorder();
    const int w = s.width(), h = s.height(), n = w * h;
    QImage img(w, h, QImage::Format_RGB32);
    img.fill(Qt::black);
    auto set = [&](int px, const QColor& c) { img.setPixelColor(px % w, px / w, c); };
    switch (mode) {
        case Heatmap::None: break;
        case Heatmap::Tests: {
            // The page's rule too (rc::testsHeat): a log scale up to the shared top
            const double most = top > 0.0 ? top : scaleOf(s, mode);
            for (int px = 0; px < n; ++px)
                if (const std::optional<double> t = rc::testsHeat(rec, px, most)) set(px, palette::ramp(*t));
            break;
        }
        case Heatmap::HitMiss: {
            for (int px = 0; px < n; ++px) {
                if (rec.firstVisit(px) < 0) continue;
                const double hits = rec.hitsAt(px), misses = rec.missesAt(px);
                if (hits + misses == 0) {
                    set(px, palette::kNoLookups);  // no cache: every ray searched
                    continue;
                }
                const double f = misses / (hits + misses);
                set(px, QColor(int(40 + 215 * f), int(200 * (1 - f) + 30), 40));
            }
            break;
        }
        case Heatmap::HitRate: {
            // One fixed scale, 0 to 1: two renders side by side always share it
            for (int px = 0; px < n; ++px) {
                if (rec.firstVisit(px) < 0) continue;
                const std::optional<double> rate = hitRate(s, px);
                set(px, rate ? palette::ramp(*rate) : palette::kNoLookups);
            }
            break;
        }
        case Heatmap::VisitOrder: {
            const double last = top > 0.0 ? top : scaleOf(s, mode);
            for (int px = 0; px < n; ++px)
                if (rec.firstVisit(px) >= 0) set(px, palette::ramp(std::min(1.0, double(rec.firstVisit(px)) / last)));
            break;
        }
        case Heatmap::BeamNode: {
            const std::vector<int> labels = s.beams().labels(path);
            for (int px = 0; px < n; ++px)
                if (labels[px] >= 0) set(px, palette::label(labels[px]));
            break;
        }
    }
    return img;
}

}  // namespace rcgui
