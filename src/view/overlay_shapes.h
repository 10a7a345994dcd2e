#pragma once
/// \file
/// \brief The overlays of the ray in focus as shapes in image coordinates, each with its
/// role and label: its cylinder of safety, its blocker hull with origin, target and the
/// nearest potential blockers, the cause of its miss, and the ray. Every viewer draws
/// these, so no overlay geometry is computed twice.
#include <optional>
#include <string>
#include <vector>

#include "view/image_projector.h"
#include "view/ray_focus.h"

namespace rc {

/// What a shape stands for: a viewer picks its colour, line and fill from it.
enum class ShapeRole {
    Cylinder,        ///< the cylinder of safety around this ray (not cached)
    CachedCylinder,  ///< the active cache entry's cylinder of safety
    CylinderAxis,    ///< the cylinder's axis (a segment)
    EmptyCone,       ///< the cone of eye rays known to hit nothing (blocker+)
    EmptyConeAxis,   ///< its axis (a point)
    Hull,            ///< the blocker hull of origin and target
    Origin,          ///< the site the ray leaves
    Target,          ///< the cached object the ray goes to
    TargetPoint,     ///< a light, or a tile of a large polygon, as target (a point)
    Blocker,         ///< a potential blocker listed for the pair
    CylinderLeft,    ///< a miss: the cached cylinder the ray left
    MissedTarget,    ///< a miss: the cached object the ray did not hit first
    BlockerHit,      ///< a miss: the listed blocker the ray hit first
    Ray,             ///< the ray's segment
};

/// The role's name as written above (Cylinder, CachedCylinder, ...): a viewer outside C++
/// (the web edition's page) styles a shape by it.
const char* toString(ShapeRole r);

/// One shape: a closed outline, a segment or a point.
struct OverlayShape {
    ShapeRole role;
    Outline outline;                      ///< closed; empty for a segment or a point
    std::optional<ImageSegment> segment;  ///< a segment (the ray, an axis)
    std::optional<ImagePoint> point;      ///< a marker
    bool covers = false;  ///< the outline holds the whole clip rectangle (tint it, do not stroke it)
    bool flat = false;    ///< the outline is a polygon's (it may hold much of the view: outline only)
    int object = -1;      ///< the scene object it outlines, -1 for none
    std::string label{};  ///< e.g. "blocker #12"
};

/// Which overlays to make.
struct ShapeChoice {
    bool cylinder = false;
    bool hull = false;
};

/// The shapes of `f`, in drawing order (the ray last), clipped to `proj`'s rectangle.
/// The hull's blockers are those FocusHull keeps (the nearest, FocusHull::kShown at most).
std::vector<OverlayShape> focusShapes(const SessionState& s, const RayFocus& f, const ImageProjector& proj,
                                      ShapeChoice choice);

/// The outline of scene object `object` (its polygon, or its bounding sphere's silhouette).
OverlayShape objectShape(const Scene& scene, int object, const ImageProjector& proj, ShapeRole role);

}  // namespace rc
