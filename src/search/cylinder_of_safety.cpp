#include "search/cylinder_of_safety.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "search/object_test.h"
#include "search/segment_clearance.h"

namespace rc {

CylinderOfSafety::CylinderOfSafety(const Scene& scene, const CompleteSearch& search)
    : scene_(scene), search_(search), slack_(1e-9 * scene.extent()) {}

Vec3 CylinderOfSafety::segmentEnd(const Query& q, const Answer& a) const {
    if (a.object >= 0) return q.ray.at(a.t);
    if (q.tmax < kNoHit) return q.ray.at(q.tmax);
    // Nothing lies outside the scene's bounding sphere: the segment ends where the ray leaves it
    const SphereRoots r = sphereRootsStable(q.ray, scene_.bound);
    return q.ray.at(r.hit ? std::max(0.0, r.t1) : 0.0);
}

void CylinderOfSafety::keep(const Query& q, const Answer& a, CacheEntry& e) const {
    e.cylinder = {q.ray.o, segmentEnd(q, a), -1.0};
    e.pending = true;
    // The object that was nearest the last segment is likely near this one: its distance
    // bounds the radius from above, so a ray straying farther misses with no search at all
    e.cylinderBelow = kNoHit;
    const int leaving = e.origin.inside ? -1 : e.origin.object;
    if (e.nearObject >= 0 && e.nearObject != e.object && e.nearObject != leaving) {
        SegmentClearance measure(e.cylinder.a, e.cylinder.b, -1, -1, kNoHit, -kNoHit);
        e.cylinderBelow = measure.distance(scene_.objects[e.nearObject].bound) - slack_;
    }
}

void CylinderOfSafety::build(CacheEntry& e, Counters& n) const {
    // [build-cylinder]
    // The radius is the distance from the segment to the nearest other surface: every
    // object's bounding sphere but the one hit and the one the ray cannot meet again.
    // Only objects near the segment can set it; the search finds them (and may cap it)
    const int leaving = e.origin.inside ? -1 : e.origin.object;
    const double clear = search_.clearance(e.cylinder.a, e.cylinder.b, e.object, leaving, search_.nearRadius());
    e.cylinder.radius = clear - slack_;
    // [build-cylinder]
    e.pending = false;
    ++n.cylindersBuilt;
}

void CylinderOfSafety::buildFor(CacheEntry& e, double need, Counters& n) const {
    // [lazy-cylinder]
    // RayCache's addition: most cylinders are too narrow for the very next ray (cube:8,
    // blocker, bfs: 56,782 of 65,061). Any object nearer the kept segment than the new
    // ray strays shows it, and the search stops at the first such object it finds
    if (need > e.cylinderBelow) {
        ++n.cylindersRuledOut;
        return;
    }
    const int leaving = e.origin.inside ? -1 : e.origin.object;
    const double stop = need + slack_;
    const double clear =
        search_.clearance(e.cylinder.a, e.cylinder.b, e.object, leaving, search_.nearRadius(), stop, &e.nearObject);
    // The radius would be at most clear - slack: if the ray needs more, it leaves it
    if (clear < stop && need > clear - slack_) {
        e.cylinderBelow = clear - slack_;
        ++n.cylindersRuledOut;
        return;
    }
    // It may fit: the cylinder is built in full, for this ray and those after it (the
    // search has already measured it, unless it stopped at the very edge)
    if (clear >= stop) {
        e.cylinder.radius = clear - slack_;
        e.pending = false;
        ++n.cylindersBuilt;
    } else {
        build(e, n);
    }
    // [lazy-cylinder]
}

Lookup CylinderOfSafety::probe(const Query& q, CacheEntry& e, Counters& n) const {
    // [probe-cylinder]
    Answer a;
    if (e.object >= 0) {
        // Test the cached object first
        ++n.intersectionTests;
        keepNearer(scene_, q, e.object, a);
        if (a.object < 0) return {false, {}, Decision::Miss, MissReason::TargetMissed};
    }
    // Then the new segment must stay inside the cylinder of safety (built the first time
    // a segment may fit in it)
    ++n.cylinderTests;
    const Vec3 end = segmentEnd(q, a);
    // [probe-cylinder]
    // BEGIN SOLUTION 02
    // [probe-contains]
    // The capsule is convex: both ends inside is enough. A ray from the kept segment's own
    // start (an eye ray after an eye ray) strays 0 there: the distance of a segment's end
    // point is exactly 0, so it is not measured
    const double fromStart = q.ray.o == e.cylinder.a ? 0.0 : e.cylinder.distance(q.ray.o);
    const double strays = std::max(fromStart, e.cylinder.distance(end));
    if (e.pending) buildFor(e, strays, n);
    if (!(strays <= e.cylinder.radius)) return {false, {}, Decision::Miss, MissReason::LeftCylinder};
    // [probe-contains]
    // END SOLUTION
    // BEGIN STUB
    // // Tutorial 02's rc::SafetyCylinder::contains decides. The cylinder is built whenever
    // // it may be needed at all (need 0), not only when the new segment may fit in it
    // if (e.pending) buildFor(e, 0.0, n);
    // if (!e.cylinder.contains(q.ray.o, end)) return {false, {}, Decision::Miss, MissReason::LeftCylinder};
    // END STUB
    return {true, a, Decision::Hit, MissReason::None};
}

}  // namespace rc
