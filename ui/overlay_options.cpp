#include "overlay_options.h"

#include "view/overlay_registry.h"
#include "view/viewer_settings.h"

namespace rcgui {

QString toString(Heatmap h) {
    // The core's names (rc::heatmapNames), in the enum's order
    return QString::fromStdString(rc::heatmapNames().at(std::size_t(h)));
}

std::optional<Heatmap> parseHeatmap(const QString& s) {
    const auto& names = rc::heatmapNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (QString::fromStdString(names[i]) == s.trimmed().toLower()) return Heatmap(i);
    return std::nullopt;
}

std::optional<Overlays> Overlays::parse(const QString& list) {
    Overlays o;
    for (const QString& raw : list.split(',', Qt::SkipEmptyParts)) {
        const QString w = raw.trimmed().toLower();
        // Names and aliases are the core's (rc::overlayRegistry), as the page's
        if (o.turnOn(rc::overlayNamed(w.toStdString()))) continue;
        if (w == "all") o.cylinder = o.hull = o.frontier = o.misses = o.samples = true;
        else if (w == "none") o.cylinder = o.hull = o.frontier = o.misses = o.samples = false;
        else return std::nullopt;
    }
    return o;
}

bool Overlays::turnOn(const std::string& name) {
    if (name == "cylinder") cylinder = true;
    else if (name == "hull") hull = true;
    else if (name == "frontier") frontier = true;
    else if (name == "misses") misses = true;
    else if (name == "samples") samples = true;
    else if (name == "grid") grid = true;
    else return false;
    return true;
}

}  // namespace rcgui
