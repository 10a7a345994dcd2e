#include "overlay_options.h"

#include "view/overlay_registry.h"

namespace rcgui {

QString toString(Heatmap h) {
    switch (h) {
        case Heatmap::None: return "none";
        case Heatmap::Tests: return "tests";
        case Heatmap::HitMiss: return "hitmiss";
        case Heatmap::HitRate: return "hitrate";
        case Heatmap::VisitOrder: return "order";
        case Heatmap::BeamNode: return "beam";
    }
    return "none";
}

std::optional<Heatmap> parseHeatmap(const QString& s) {
    for (Heatmap h : {Heatmap::None, Heatmap::Tests, Heatmap::HitMiss, Heatmap::HitRate, Heatmap::VisitOrder, Heatmap::BeamNode})
        if (toString(h) == s.trimmed().toLower()) return h;
    return std::nullopt;
}

std::optional<Overlays> Overlays::parse(const QString& list) {
    Overlays o;
    for (const QString& raw : list.split(',', Qt::SkipEmptyParts)) {
        const QString w = raw.trimmed().toLower();
        // Names and aliases are the core's (rc::overlayRegistry), as the page's
        const std::string name = rc::overlayNamed(w.toStdString());
        if (name == "cylinder") o.cylinder = true;
        else if (name == "hull") o.hull = true;
        else if (name == "frontier") o.frontier = true;
        else if (name == "misses") o.misses = true;
        else if (name == "samples") o.samples = true;
        else if (name == "grid") o.grid = true;
        else if (w == "all") o.cylinder = o.hull = o.frontier = o.misses = o.samples = true;
        else if (w == "none") o.cylinder = o.hull = o.frontier = o.misses = o.samples = false;
        else return std::nullopt;
    }
    return o;
}

}  // namespace rcgui
