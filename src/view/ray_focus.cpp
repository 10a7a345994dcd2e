#include "view/ray_focus.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/portable_math.h"
#include "search/standard_algorithm.h"

namespace rc {

rc::Vec3 RayFocus::segmentEnd(const rc::Scene& scene) const {
    if (hit >= 0 && t >= 0.0) return ray.at(t);
    if (tmax >= 0.0) return ray.at(tmax);
    const rc::SphereRoots r = rc::sphereRootsStable(ray, scene.bound);
    return ray.at(r.hit ? std::max(0.0, r.t1) : 0.0);
}

std::optional<RayFocus> RayFocus::ofCurrent(const SessionState& s) {
    const auto& e = s.recorder().lastEvent();
    if (!e) return std::nullopt;
    RayFocus f;
    const rc::Query& q = e->task.query;
    f.event = int(s.recorder().events().size()) - 1;
    f.decision = e->lookup.decision;
    f.reason = e->lookup.reason;
    f.tests = int(e->tests);
    f.pixel = e->task.pixel;
    f.node = e->task.node;
    f.kind = q.kind;
    f.light = q.light;
    f.origin = q.origin;
    f.hit = e->lookup.known ? e->lookup.answer().object : -1;
    f.ray = q.ray;
    f.t = f.hit >= 0 ? e->lookup.answer().t : -1.0;
    f.tmax = q.tmax < rc::kNoHit ? q.tmax : -1.0;
    f.current = true;
    f.deferred = e->deferred;
    return f;
}

std::optional<RayFocus> RayFocus::ofEvent(const SessionState& s, int index) {
    const auto& events = s.recorder().events();
    if (index < 0 || std::size_t(index) >= events.size()) return std::nullopt;
    // The newest event is the one being traced: its full-precision copy, and its entry
    if (std::size_t(index) + 1 == events.size())
        if (auto f = ofCurrent(s)) return f;
    // Its ray traced again when the log keeps none
    const EventRecord r = s.event(std::size_t(index));
    RayFocus f;
    f.event = index;
    f.decision = r.rayDecision();
    f.reason = r.missReason();
    f.tests = r.tests;
    f.pixel = r.pixel;
    f.node = r.node;
    f.kind = r.rayKind();
    f.light = s.session().cacheTree().node(r.node).light;
    f.origin = {r.origin, bool(r.flags & EventRecord::Inside)};
    f.hit = r.hit;
    f.ray = {r.rayOrigin(), r.rayDirection()};
    f.t = r.t;
    // A shadow ray ends at its light
    if (f.kind == rc::RayKind::Shadow && f.light >= 0 && std::size_t(f.light) < s.scene().lights.size())
        f.tmax = glm::length(s.scene().lights[std::size_t(f.light)].position - f.ray.o);
    f.deferred = r.deferred();
    return f;
}

std::optional<RayFocus> RayFocus::of(const SessionState& s, const Selection& sel) {
    std::optional<RayFocus> f;
    if (sel.event >= 0) {
        f = ofEvent(s, sel.event);
    } else if (sel.pixel >= 0) {
        if (sel.pixel < s.width() * s.height()) f = ofEvent(s, s.recorder().eventAt(sel.pixel, 0));
    } else {
        f = ofCurrent(s);
        return f;
    }
    if (f) f->selected = true;
    return f;
}

rc::SafetyCylinder cylinderAround(const rc::Scene& scene, const RayFocus& f) {
    const rc::Vec3 from = f.ray.o;
    const rc::Vec3 to = f.segmentEnd(scene);
    // Every object's bounding sphere but the one the ray cannot meet again: the one
    // rc::standardTest (tutorial 01's hole) passes over without a counted test. The radius
    // is rc::safetyRadius's (tutorial 02's hole). In a student build both are the student's
    rc::Query q;
    q.ray = f.ray;
    q.origin = f.origin;
    std::vector<rc::Sphere> spheres;
    spheres.reserve(std::size_t(scene.size()));
    int hit = -1;
    for (int id = 0; id < scene.size(); ++id) {
        rc::Counters tested;
        rc::Answer unused;
        rc::standardTest(scene, q, id, unused, tested);
        if (tested.intersectionTests == 0) continue;
        if (id == f.hit) hit = int(spheres.size());
        spheres.push_back(scene.objects[id].bound);
    }
    const double radius = rc::safetyRadius(spheres, hit, from, to);
    return {from, to, radius < rc::kNoHit ? radius : -1.0};
}

double emptyConeAround(const rc::Scene& scene, const RayFocus& f) {
    // BEGIN SOLUTION 07
    if (f.origin.object >= 0 || f.hit >= 0) return -1.0;
    double angle = rc::kNoHit;
    for (const rc::Object& o : scene.objects) {
        const rc::Vec3 v = o.bound.c - f.ray.o;
        const double dist = glm::length(v);
        if (dist <= o.bound.r) return -1.0;
        const double between = std::atan2(glm::length(glm::cross(f.ray.d, v)), glm::dot(f.ray.d, v));
        angle = std::min(angle, between - pm::asin(o.bound.r / dist));
    }
    return angle < rc::kNoHit ? angle : -1.0;
    // END SOLUTION
    // BEGIN STUB
    // // The widest empty cone is tutorial 07's basic part: this edition draws none
    // (void)scene, (void)f;
    // return -1.0;
    // END STUB
}

FocusHull hullOf(const SessionState& s, const RayFocus& f) {
    FocusHull h;
    const rc::BlockerLists* lists = s.session().strategy().blockerLists();
    if (!lists) return h;
    h.coneAxis = f.ray.d;
    // The pair of sites of the ray itself: where it leaves (its tile, on a tiled polygon)
    // and what it hit (the light, for a shadow ray); the core keeps no copy for display
    h.origin = f.origin.object >= 0 ? lists->pointSite(f.origin.object, f.ray.o) : lists->eyeSite();
    h.target = f.kind == rc::RayKind::Shadow ? lists->lightSite(f.light)
               : f.hit >= 0                  ? lists->pointSite(f.hit, f.ray.at(f.t))
                                             : -1;
    if (f.current) {
        const rc::CacheEntry& e = s.session().cacheTree().entry(f.node);
        if (e.state == rc::CacheEntry::State::Loaded && e.object < 0 && e.coneAngle >= 0.0) {
            h.coneAxis = e.coneAxis;
            h.coneAngle = e.coneAngle;
        }
    } else {
        h.coneAngle = emptyConeAround(s.scene(), f);
    }
    // No target (a ray that hit nothing) or no entry yet: there is no hull
    if (h.origin < 0 || h.target < 0 || h.origin >= lists->sites() || h.target >= lists->sites()) {
        h.origin = h.target = -1;
        return h;
    }
    h.a = lists->siteSphere(h.origin);
    h.b = lists->siteSphere(h.target);
    h.targetObject = lists->siteObject(h.target);
    if (const std::vector<int>* blockers = lists->find(h.origin, h.target))
        for (int id : *blockers)
            if (id >= 0 && id < s.scene().size()) h.blockers.push_back(id);
    h.listed = h.blockers.size();
    // Keep the blockers nearest the segment between origin and target, nearest first
    const rc::Scene& scene = s.scene();
    auto gap = [&](int id) {
        const rc::Sphere& b = scene.objects[std::size_t(id)].bound;
        return rc::segmentDistance(b.c, h.a.c, h.b.c) - b.r;
    };
    auto nearer = [&](int x, int y) {
        const double gx = gap(x), gy = gap(y);
        return gx < gy || (gx == gy && x < y);
    };
    const std::size_t keep = std::min(h.blockers.size(), FocusHull::kShown);
    std::partial_sort(h.blockers.begin(), h.blockers.begin() + std::ptrdiff_t(keep), h.blockers.end(), nearer);
    h.blockers.resize(keep);
    return h;
}

FocusCylinder cylinderOf(const SessionState& s, const RayFocus& f) {
    FocusCylinder c;
    if (f.current) {
        const rc::CacheEntry& e = s.session().cacheTree().entry(f.node);
        if (e.state == rc::CacheEntry::State::Loaded && e.cylinder.radius >= 0.0) {
            c.cylinder = e.cylinder;
            c.cached = true;
            return c;
        }
    }
    c.cylinder = cylinderAround(s.scene(), f);
    return c;
}

}  // namespace rc
