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
    : CacheStrategy(scene, search), lists_(scene) {}

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
        // Nothing was hit: an empty cone around the last eye ray, else the cylinder
        if (q.origin.object >= 0) return probeCylinder(q, e, n);
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
    for (int id : lists_.get(lists_.originSite(q.origin), e.object, n))
        testObject(scene_, q, id, best, n);
    if (best.object != e.object) return {true, best, Decision::Miss, MissReason::BlockerHit};
    return {true, best, Decision::Hit};
    // [blocker-probe]
}

Lookup BlockerCache::shadow(const Query& q, const CacheEntry& e, MissReason why, Counters& n) {
    // [blocker-shadow]
    // Every object that can stand between a surface and its light meets their hull
    Answer best;
    for (int id : lists_.get(lists_.originSite(q.origin), lists_.lightSite(q.light), n))
        testObject(scene_, q, id, best, n);
    if (why != MissReason::None) return {true, best, Decision::Miss, why};
    if (best.object == e.object) return {true, best, Decision::Hit};
    return {true, best, Decision::Miss,
            best.object >= 0 ? MissReason::BlockerHit : MissReason::TargetMissed};
    // [blocker-shadow]
}

void BlockerCache::reload(const Query& q, const Answer& a, CacheEntry& e, Counters& n) {
    e.state = CacheEntry::State::Loaded;
    e.origin = q.origin;
    e.object = a.object;
    e.cylinder.radius = -1.0;
    e.coneAngle = -1.0;
    e.blockerOrigin = lists_.originSite(q.origin);
    if (q.kind == RayKind::Shadow) {
        e.blockerTarget = lists_.lightSite(q.light);
    } else if (a.object >= 0) {
        e.blockerTarget = a.object;
        lists_.get(e.blockerOrigin, e.blockerTarget, n);
    } else {
        e.blockerTarget = -1;
        if (q.origin.object < 0) buildCone(q, e, n);
        else buildCylinder(q, a, e, n);
    }
}

void BlockerCache::buildCone(const Query& q, CacheEntry& e, Counters& n) const {
    // [empty-cone]
    // The widest cone around this empty eye ray that no sphere's silhouette enters
    double angle = kNoHit;
    for (const Object& o : scene_.objects) {
        const Vec3 v = o.bound.c - q.ray.o;
        const double dist = glm::length(v);
        if (dist <= o.bound.r) { angle = -1.0; break; }  // the eye is inside: no cone
        angle = std::min(angle, angleBetween(q.ray.d, v) - std::asin(o.bound.r / dist));
    }
    e.coneAxis = q.ray.d;
    e.coneAngle = angle - 1e-9;
    // [empty-cone]
    ++n.cylindersBuilt;
}

}  // namespace rc
