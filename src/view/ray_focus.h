#pragma once
/// \file
/// \brief The ray an overlay is drawn for: the one being traced, or one of a selected pixel.
#include <optional>
#include <vector>

#include "view/event_record.h"
#include "view/session_state.h"

namespace rc {

/// What is selected in the window.
struct Selection {
    int pixel = -1;      ///< selected pixel, -1 for none
    int event = -1;      ///< its ray chosen in the ray tree (index into the recorder), -1: its eye ray
    int object = -1;     ///< object highlighted from the objects panel, -1 for none
};

/// One ray, with what the overlays need to know about it.
struct RayFocus {
    int event = -1;       ///< index of its record in the recorder

    int pixel = 0;
    int node = 0;         ///< ray-tree path
    rc::RayKind kind = rc::RayKind::Primary;
    int light = -1;       ///< shadow rays: the light
    rc::RayOrigin origin;
    int hit = -1;         ///< object hit, -1 for nothing
    rc::Ray ray;
    double t = -1.0;      ///< hit distance, < 0 for none
    double tmax = -1.0;   ///< shadow rays: distance to the light
    bool current = false; ///< the ray being traced (its path's cache entry is the active one)
    bool deferred = false;
    bool selected = false; ///< chosen by the user (else the ray being traced)
    rc::Decision decision = rc::Decision::Uncached;
    rc::MissReason reason = rc::MissReason::None;
    int tests = 0;

    /// Where the ray's segment ends: its hit, its light, or where it leaves the scene.
    rc::Vec3 segmentEnd(const rc::Scene& scene) const;

    /// The ray of the last trace event, if any.
    static std::optional<RayFocus> ofCurrent(const SessionState& s);
    /// The ray of recorded event `index`; nothing when there is no such event.
    static std::optional<RayFocus> ofEvent(const SessionState& s, int index);
    /// The ray in focus (the rule every view follows): the ray chosen in the ray tree or
    /// event log, else the eye ray of the selected pixel (nothing while it is untraced),
    /// else the ray being traced.
    static std::optional<RayFocus> of(const SessionState& s, const Selection& sel);
};

/// The blocker hull of a ray in focus: its origin and target sites, as the blocker cache
/// keys them, and the potential blockers listed for the pair.
struct FocusHull {
    int origin = -1, target = -1;  ///< blocker-list sites (-1: none, e.g. a ray that hit nothing)
    rc::Sphere a, b;               ///< their spheres
    int targetObject = -1;         ///< the object the target site stands for (-1: a light)
    std::vector<int> blockers;     ///< the nearest listed potential blockers, nearest first (at most kShown)
    std::size_t listed = 0;        ///< how many the list holds (blockers.size() when all are kept)
    /// Blockers kept for drawing: an overlay costs what the eye can take in, not what the
    /// list holds (the ground polygon of SPD's balls can list the whole scene).
    static constexpr std::size_t kShown = 60;
    rc::Vec3 coneAxis{0, 0, 1};    ///< an eye ray that hit nothing: the empty cone's axis
    double coneAngle = -1.0;       ///< ... and its half angle (< 0: none)
    bool valid() const { return origin >= 0 && target >= 0; }
};

/// The hull the overlays and the scene view draw for `f`: the pair of sites the blocker
/// cache keys for the ray (its origin's, and its hit's or light's), with the active entry's
/// empty cone when `f` is the ray being traced. Empty without blocker lists.
FocusHull hullOf(const SessionState& s, const RayFocus& f);

/// The cylinder of safety drawn for `f`: the active entry's (`cached`) when it has one,
/// else the one around its segment. radius < 0: none.
struct FocusCylinder {
    rc::SafetyCylinder cylinder;
    bool cached = false;
};
FocusCylinder cylinderOf(const SessionState& s, const RayFocus& f);

/// The Speer-DeRose-Barsky cylinder of safety around a ray's segment: the largest
/// capsule no other object's bounding sphere enters (radius < 0 if none).
rc::SafetyCylinder cylinderAround(const rc::Scene& scene, const RayFocus& f);

/// The widest cone of eye rays around `f`'s direction that no bounding sphere enters,
/// as the blocker cache builds it for an eye ray that hits nothing (< 0: none).
double emptyConeAround(const rc::Scene& scene, const RayFocus& f);

}  // namespace rc
