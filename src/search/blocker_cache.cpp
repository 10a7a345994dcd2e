#include "search/blocker_cache.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rc {

namespace {
double angleBetween(const Vec3& u, const Vec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}
}  // namespace

BlockerCache::BlockerCache(const Scene& scene, const CompleteSearch& search)
    : CacheStrategy(scene, search), lists_(scene, search) {}

Lookup BlockerCache::lookup(const Query& q, CacheEntry& e, LookupMode mode, Counters& n) {
    const MissReason why = unusable(q, e);
    // Shadow rays: the hull of origin and light holds every possible blocker
    if (q.kind == RayKind::Shadow) {
        Lookup r = shadow(q, e, why, n);
        if (mode == LookupMode::Full && r.decision == Decision::Miss) reload(q, r.answer, e, n);
        return r;
    }
    Lookup r;
    if (why == MissReason::None) {
        r = probe(q, e, n);
        if (r.known) {
            if (mode == LookupMode::Full && r.decision == Decision::Miss) reload(q, r.answer, e, n);
            return r;
        }
    } else {
        r.reason = why;
    }
    if (mode == LookupMode::CheapOnly) return {false, {}, Decision::Miss, r.reason};
    return searchAndReload(q, e, r.reason, n);
}

Lookup BlockerCache::probe(const Query& q, CacheEntry& e, Counters& n) {
    if (e.object < 0) {
        // Nothing was hit: the empty cone of directions around the last such ray, else the
        // cylinder, built the first time the entry is used again. Cones weigh every object;
        // in front of a grid the cylinder needs only nearby cells.
        if (e.pending) {
            if (search_.nearRadius() == kNoHit) buildCone(e, n);
            if (e.coneAngle < 0.0) buildCylinder(e, n);
            e.pending = false;
        }
        if (e.coneAngle < 0.0) return probeCylinder(q, e, n);
        ++n.coneTests;
        if (angleBetween(q.ray.d, e.coneAxis) < e.coneAngle) return {true, {}, Decision::Hit};
        return {false, {}, Decision::Miss, MissReason::LeftCone};
    }
    // [blocker-probe]
    // Test the cached sphere first
    ++n.intersectionTests;
    const double t = scene_.intersect(q.ray, e.object, q.origin);
    if (!(t < q.tmax)) return {false, {}, Decision::Miss, MissReason::TargetMissed};
    // Then only the potential blockers between origin and target can come first
    Answer best{e.object, t};
    const BlockerList& list = lists_.get(lists_.originSite(q.origin), e.object, n);
    for (std::size_t i = 0; i < list.ids.size() && list.reach[i] <= best.t; ++i)
        testObject(scene_, q, list.ids[i], best, n);
    if (best.object != e.object) return {true, best, Decision::Miss, MissReason::BlockerHit};
    return {true, best, Decision::Hit};
    // [blocker-probe]
}

Lookup BlockerCache::shadow(const Query& q, const CacheEntry& e, MissReason why, Counters& n) {
    // [blocker-shadow]
    // Every object that can stand between a surface and its light meets their hull
    Answer best;
    const BlockerList& list = lists_.get(lists_.originSite(q.origin), lists_.lightSite(q.light), n);
    for (std::size_t i = 0; i < list.ids.size() && list.reach[i] <= std::min(best.t, q.tmax); ++i)
        testObject(scene_, q, list.ids[i], best, n);
    if (why != MissReason::None) return {true, best, Decision::Miss, why};
    if (best.object == e.object) return {true, best, Decision::Hit};
    return {true, best, Decision::Miss,
            best.object >= 0 ? MissReason::BlockerHit : MissReason::TargetMissed};
    // [blocker-shadow]
}

void BlockerCache::reload(const Query& q, const Answer& a, CacheEntry& e, Counters&) {
    e.state = CacheEntry::State::Loaded;
    e.origin = q.origin;
    e.object = a.object;
    e.cylinder.radius = -1.0;
    e.coneAngle = -1.0;
    e.pending = false;
    e.blockerOrigin = lists_.originSite(q.origin);
    if (q.kind == RayKind::Shadow) {
        e.blockerTarget = lists_.lightSite(q.light);
    } else if (a.object >= 0) {
        e.blockerTarget = a.object;  // its list is built when the entry is next used
    } else {
        e.blockerTarget = -1;
        e.coneAxis = q.ray.d;
        keepSegment(q, a, e);
    }
}

void BlockerCache::buildCone(CacheEntry& e, Counters& n) const {
    // [empty-cone]
    // Rays leave from anywhere in the origin's sphere (a point for the eye): direction d
    // misses sphere j if its angle theta_j to c_j exceeds beta_j = asin((r_j + r_origin) / dist)
    const Sphere from = lists_.siteSphere(lists_.originSite(e.origin));
    const Vec3 axis = e.coneAxis;
    const double reach = from.r + slack_;
    // First pass without trigonometry: the smallest theta_j - beta_j has the largest cosine
    std::vector<double>& cosines = coneScratch_;
    cosines.assign(std::size_t(scene_.size()), -2.0);
    double best = -2.0;
    for (int id = 0; id < scene_.size(); ++id) {
        // A ray leaving an object outward cannot meet it again; one heading into it can
        if (id == e.origin.object && !e.origin.inside) continue;
        const Sphere& s = scene_.objects[id].bound;
        const Vec3 v = s.c - from.c;
        const double dist = glm::length(v);
        const double sinB = (s.r + reach) / dist;
        if (!(sinB < 1.0)) { best = 2.0; break; }  // touching the origin: no cone
        const double cosB = std::sqrt(1.0 - sinB * sinB);
        const double sinT = glm::length(glm::cross(axis, v)) / dist, cosT = glm::dot(axis, v) / dist;
        if (sinT * cosB - cosT * sinB < 0.0) { best = 2.0; break; }  // d points into j's cone
        cosines[id] = cosT * cosB + sinT * sinB;
        best = std::max(best, cosines[id]);
    }
    // Second pass, exact angles for the few nearest the axis
    double angle = best > 1.0 ? -1.0 : kNoHit;
    for (int id = 0; id < scene_.size() && angle > 0.0; ++id) {
        if (cosines[id] < best - 1e-12) continue;
        const Sphere& s = scene_.objects[id].bound;
        const Vec3 v = s.c - from.c;
        angle = std::min(angle, angleBetween(axis, v) - std::asin((s.r + reach) / glm::length(v)));
    }
    e.coneAngle = angle - 1e-9;
    // [empty-cone]
    ++n.cylindersBuilt;
}

}  // namespace rc
