#pragma once
/// \file
/// \brief The viewer's colours and each overlay role's style, once for both front ends: the
/// Qt GUI (ui/palette.h turns them into QColors, ui/overlay_painter.cpp draws each role by
/// roleStyle()) and the web page (through the bindings' `palette()`). Chosen to read well on
/// a projector and for colour-blind viewers (miss reasons use the Okabe-Ito palette).
/// RayCache's own addition.
#include <cstdint>

#include "search/counters.h"
#include "view/overlay_shapes.h"

namespace rc {

/// An 8-bit sRGB colour.
struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

namespace colours {
inline constexpr Rgb kRay{255, 235, 59};           ///< the ray being traced
inline constexpr Rgb kCylinder{0, 229, 255};       ///< cylinder of safety
inline constexpr Rgb kHull{224, 64, 251};          ///< blocker hull
inline constexpr Rgb kTarget{0, 230, 118};         ///< target sphere of a blocker list
inline constexpr Rgb kBlocker{255, 145, 0};        ///< potential blockers
inline constexpr Rgb kOrigin{255, 255, 255};       ///< origin sphere of a blocker list
inline constexpr Rgb kQueued{118, 255, 3};         ///< breadth-first queue
inline constexpr Rgb kDeferred{255, 23, 68};       ///< deferred seeds
inline constexpr Rgb kRegion{255, 255, 255};       ///< the region being filled
inline constexpr Rgb kRegionEdge{20, 20, 24};      ///< the edges of finished regions
inline constexpr Rgb kSelection{0, 176, 255};      ///< selected pixel and object
inline constexpr Rgb kMissCause{255, 64, 64};      ///< what made a miss: the target missed, the cylinder left
inline constexpr Rgb kLight{255, 214, 0};          ///< lights: their stars and spheres
inline constexpr Rgb kSampleRay{255, 255, 255};    ///< eye and reflection samples that hit an object
inline constexpr Rgb kSampleMissed{140, 150, 255}; ///< samples that hit nothing
inline constexpr Rgb kShadowLit{255, 250, 190};    ///< shadow samples that reach the light
inline constexpr Rgb kShadowBlocked{255, 40, 130}; ///< shadow samples an object stops
inline constexpr Rgb kNoLookups{110, 110, 110};    ///< heatmaps: a pixel with no cache lookups
inline constexpr Rgb kMissText{200, 90, 0};        ///< the ray tree's rows, on a light background: a miss
inline constexpr Rgb kDeferredText{200, 40, 60};   ///< ... a deferred attempt
/// Opacity (of 255) of the region being filled over the picture: a tint it shows through
inline constexpr std::uint8_t kRegionOpacity = 120;
/// Opacity (of 255) of finished regions' edges: nearly solid, so that the regions read
inline constexpr std::uint8_t kRegionEdgeOpacity = 220;
}  // namespace colours

/// Colour of a miss reason's markers and key entry.
Rgb missReasonColour(MissReason r);

enum class FanOutcome;  // view/sample_fan.h
/// Colour of a sample ray by what became of it: hit, missed, lit or blocked.
Rgb fanOutcomeColour(FanOutcome o);

/// The heatmaps' perceptual colour map (viridis-like) of t in [0, 1] (clamped).
Rgb heatRamp(double t);

/// How a role of rc::ShapeRole is drawn. Widths and star radii are in screen pixels.
struct RoleStyle {
    Rgb colour;
    double width = 0.0;  ///< line width (0 for a star)
    bool dashed = false;
    int fill = 0;        ///< fill alpha, 0-255, of a closed outline (a flat one is never filled)
    double star = 0.0;   ///< > 0: the role is a point, drawn as a star of this radius
    int arms = 0;        ///< the star's arms: 2 (a diagonal cross) or 4
};
RoleStyle roleStyle(ShapeRole role);

/// Every ShapeRole, in its declared order.
inline constexpr int kShapeRoles = int(ShapeRole::Ray) + 1;

}  // namespace rc
