#pragma once
/// \file
/// \brief Which overlays and which picture (image or a heatmap) the view shows.
#include <optional>

#include <QString>
#include <QStringList>

namespace rcgui {

/// What replaces the rendered image in the view.
enum class Heatmap {
    None,        ///< the image itself
    Tests,       ///< intersection tests per pixel
    HitMiss,     ///< share of cache hits and misses per pixel
    HitRate,     ///< cache hit rate per pixel, hits / (hits + misses), on a fixed 0-1 scale
    VisitOrder,  ///< when each pixel was first visited
    BeamNode,    ///< beam-tree node of each pixel at the current path
};
QString toString(Heatmap h);
std::optional<Heatmap> parseHeatmap(const QString& s);

/// The overlay toggles.
struct Overlays {
    bool cylinder = false;  ///< cylinder of safety of the active cache entry
    bool hull = false;      ///< blocker hull ("cone"), blockers and target
    bool frontier = false;  ///< breadth-first queue, deferred seeds and regions
    bool misses = false;    ///< miss markers coloured by reason
    bool samples = false;   ///< the sample rays of the pixel in focus (eye, shadow, gloss)
    bool grid = true;       ///< pixel grid at high zoom
    bool legend = true;     ///< the colour key
    double lineScale = 1.0; ///< line width factor (Large fonts draw thicker lines)

    /// Parses "cylinder,cone,frontier,misses,samples" (also "hull", "grid", "all", "none").
    static std::optional<Overlays> parse(const QString& list);
    /// Turns on the overlay registered as `name` (rc::overlayRegistry); false for no such name.
    bool turnOn(const std::string& name);
};

}  // namespace rcgui
