#pragma once
/// \file
/// \brief The GUI's colours: the core's (view/palette.h, which the web page shares), as QColors.
#include <QColor>

#include "search/counters.h"
#include "view/palette.h"
#include "view/sample_fan.h"

namespace rcgui::palette {

/// The core's colour as a QColor.
inline QColor qt(rc::Rgb c, int alpha = 255) { return QColor(c.r, c.g, c.b, alpha); }

/// Colour of a miss reason's markers and legend entry.
QColor missReason(rc::MissReason r);

inline const QColor kRay = qt(rc::colours::kRay);  ///< the ray being traced
inline const QColor kCylinder = qt(rc::colours::kCylinder);  ///< cylinder of safety
inline const QColor kHull = qt(rc::colours::kHull);  ///< blocker hull
inline const QColor kTarget = qt(rc::colours::kTarget);  ///< target sphere of a blocker list
inline const QColor kBlocker = qt(rc::colours::kBlocker);  ///< potential blockers
inline const QColor kOrigin = qt(rc::colours::kOrigin);  ///< origin sphere of a blocker list
inline const QColor kQueued = qt(rc::colours::kQueued);  ///< breadth-first queue
inline const QColor kDeferred = qt(rc::colours::kDeferred);  ///< deferred seeds
inline const QColor kRegion = qt(rc::colours::kRegion);  ///< the region being filled
inline const QColor kRegionEdge = qt(rc::colours::kRegionEdge);  ///< the edges of finished regions
inline const QColor kSelection = qt(rc::colours::kSelection);  ///< selected pixel and object
inline const QColor kMissCause = qt(rc::colours::kMissCause);  ///< what made a miss: the target missed, the cylinder left
inline const QColor kLight = qt(rc::colours::kLight);  ///< lights: their stars and spheres
inline const QColor kSampleRay = qt(rc::colours::kSampleRay);  ///< eye and reflection samples that hit an object
inline const QColor kSampleMissed = qt(rc::colours::kSampleMissed);  ///< samples that hit nothing (they leave the scene)
inline const QColor kShadowLit = qt(rc::colours::kShadowLit);  ///< shadow samples that reach the light
inline const QColor kShadowBlocked = qt(rc::colours::kShadowBlocked);  ///< shadow samples an object stops
inline const QColor kNoLookups = qt(rc::colours::kNoLookups);  ///< heatmaps: a pixel with no cache lookups

/// `c` with opacity `a` (of 255).
inline QColor withAlpha(QColor c, int a) {
    c.setAlpha(a);
    return c;
}

/// Colour of a sample ray by its outcome: hit, missed, lit or blocked.
QColor fanOutcome(rc::FanOutcome o);

/// A distinct, stable colour for a label (regions, beams).
QColor label(std::int64_t id, int alpha = 255);

/// A perceptual colour map (viridis-like) of t in [0, 1].
QColor ramp(double t);

}  // namespace rcgui::palette
