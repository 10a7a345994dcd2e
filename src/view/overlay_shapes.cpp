#include "view/overlay_shapes.h"

#include "view/miss_cause.h"

namespace rc {

namespace {

OverlayShape outlineShape(ShapeRole role, Outline outline, const ImageProjector& proj, std::string label = {}) {
    OverlayShape s{role, std::move(outline), std::nullopt, std::nullopt};
    s.covers = proj.covers(s.outline);
    s.label = std::move(label);
    return s;
}

void addCapsule(std::vector<OverlayShape>& out, const SafetyCylinder& c, const ImageProjector& proj, ShapeRole role,
                std::string label) {
    out.push_back(outlineShape(role, proj.hull({c.a, c.radius}, {c.b, c.radius}), proj, std::move(label)));
}

}  // namespace

const char* toString(ShapeRole r) {
    switch (r) {
        case ShapeRole::Cylinder: return "Cylinder";
        case ShapeRole::CachedCylinder: return "CachedCylinder";
        case ShapeRole::CylinderAxis: return "CylinderAxis";
        case ShapeRole::EmptyCone: return "EmptyCone";
        case ShapeRole::EmptyConeAxis: return "EmptyConeAxis";
        case ShapeRole::Hull: return "Hull";
        case ShapeRole::Origin: return "Origin";
        case ShapeRole::Target: return "Target";
        case ShapeRole::TargetPoint: return "TargetPoint";
        case ShapeRole::Blocker: return "Blocker";
        case ShapeRole::CylinderLeft: return "CylinderLeft";
        case ShapeRole::MissedTarget: return "MissedTarget";
        case ShapeRole::BlockerHit: return "BlockerHit";
        case ShapeRole::Ray: return "Ray";
    }
    return "?";
}

OverlayShape objectShape(const Scene& scene, int object, const ImageProjector& proj, ShapeRole role) {
    const Object& obj = scene.objects[std::size_t(object)];
    // Polygons (ground planes) may cover the whole view: outlined only
    const bool flat = obj.shape == Shape::Polygon;
    OverlayShape s = outlineShape(role, flat ? proj.polygon(scene.polygons[obj.index]) : proj.silhouette(obj.bound), proj);
    s.flat = flat;
    s.object = object;
    return s;
}

// [focus-shapes]
std::vector<OverlayShape> focusShapes(const SessionState& s, const RayFocus& f, const ImageProjector& proj,
                                      ShapeChoice choice) {
    std::vector<OverlayShape> out;
    const Scene& scene = s.scene();
    auto object = [&](int id, ShapeRole role, const std::string& label) {
        if (id < 0 || id >= scene.size()) return;
        out.push_back(objectShape(scene, id, proj, role));
        out.back().label = label + " #" + std::to_string(id);
    };
    // The blocker hull: the empty cone of an eye ray that hit nothing, or the hull of its
    // pair of sites with the potential blockers listed for them
    if (choice.hull) {
        const FocusHull h = hullOf(s, f);
        if (h.coneAngle >= 0.0) {
            out.push_back(outlineShape(ShapeRole::EmptyCone, proj.eyeCone(h.coneAxis, h.coneAngle), proj, "empty cone"));
            if (const auto c = proj.point(proj.eye() + h.coneAxis))
                out.push_back({ShapeRole::EmptyConeAxis, {}, std::nullopt, *c});
        }
        if (h.valid()) {
            out.push_back(outlineShape(ShapeRole::Hull, proj.hull(h.a, h.b), proj, "blocker hull"));
            out.push_back(outlineShape(ShapeRole::Origin, proj.silhouette(h.a), proj, "origin"));
            for (int id : h.blockers) object(id, ShapeRole::Blocker, "blocker");
            if (h.target < scene.size()) object(h.target, ShapeRole::Target, "target");
            else if (const auto c = proj.point(h.b.c)) out.push_back({ShapeRole::TargetPoint, {}, std::nullopt, *c});
        }
    }
    // The cylinder of safety: the active entry's when it has one, else the one around this ray
    if (choice.cylinder) {
        const FocusCylinder fc = cylinderOf(s, f);
        if (fc.cylinder.radius > 0.0) {
            addCapsule(out, fc.cylinder, proj, fc.cached ? ShapeRole::CachedCylinder : ShapeRole::Cylinder,
                       "cylinder of safety");
            if (const auto axis = proj.segment(fc.cylinder.a, fc.cylinder.b))
                out.push_back({ShapeRole::CylinderAxis, {}, *axis, std::nullopt});
        }
    }
    if (!(choice.cylinder || choice.hull)) return out;
    // A miss: what the entry held that this ray did not keep to
    const MissCause c = missCauseOf(s, f);
    if (c.valid()) {
        if (c.cylinder.radius > 0.0) addCapsule(out, c.cylinder, proj, ShapeRole::CylinderLeft, "cylinder left");
        if (c.reason == MissReason::TargetMissed || c.reason == MissReason::BlockerHit)
            object(c.cachedObject, ShapeRole::MissedTarget, "cached target");
        object(c.blocker, ShapeRole::BlockerHit, "blocker hit");
    }
    // The ray itself, from its origin to the end of its segment
    if (const auto l = proj.segment(f.ray.o, f.segmentEnd(scene))) out.push_back({ShapeRole::Ray, {}, *l, std::nullopt});
    return out;
}
// [focus-shapes]

}  // namespace rc
