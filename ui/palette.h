#pragma once
/// \file
/// \brief The GUI's colours, chosen to read well on a projector and for colour-blind
/// viewers (miss reasons use the Okabe-Ito palette).
#include <QColor>

#include "search/counters.h"

namespace rcgui::palette {

/// Colour of a miss reason's markers and legend entry.
QColor missReason(rc::MissReason r);

inline const QColor kRay{255, 235, 59};          ///< the ray being traced
inline const QColor kCylinder{0, 229, 255};      ///< cylinder of safety
inline const QColor kHull{224, 64, 251};         ///< blocker hull
inline const QColor kTarget{0, 230, 118};        ///< target sphere of a blocker list
inline const QColor kBlocker{255, 145, 0};       ///< potential blockers
inline const QColor kOrigin{255, 255, 255};      ///< origin sphere of a blocker list
inline const QColor kQueued{118, 255, 3};        ///< breadth-first queue
inline const QColor kDeferred{255, 23, 68};      ///< deferred seeds
inline const QColor kRegion{255, 255, 255};      ///< the region being filled
inline const QColor kRegionEdge{20, 20, 24};     ///< the edges of finished regions
inline const QColor kSelection{0, 176, 255};     ///< selected pixel and object
inline const QColor kMissCause{255, 64, 64};     ///< what made a miss: the target missed, the cylinder left
inline const QColor kLight{255, 214, 0};         ///< lights: their stars and spheres
// The sample rays of the pixel in focus (none of them a miss reason's colour)
inline const QColor kSampleRay{255, 255, 255};   ///< eye and reflection samples that hit an object
inline const QColor kSampleMissed{140, 150, 255}; ///< samples that hit nothing (they leave the scene)
inline const QColor kShadowLit{255, 250, 190};   ///< shadow samples that reach the light
inline const QColor kShadowBlocked{255, 40, 130}; ///< shadow samples an object stops
inline const QColor kNoLookups{110, 110, 110};   ///< heatmaps: a pixel with no cache lookups

/// A distinct, stable colour for a label (regions, beams).
QColor label(std::int64_t id, int alpha = 255);

/// A perceptual colour map (viridis-like) of t in [0, 1].
QColor ramp(double t);

}  // namespace rcgui::palette
