#pragma once
/// \file
/// \brief How near a segment comes to the objects: the radius of a cylinder of safety.
#include "geometry/safety_cylinder.h"
#include "search/sphere_cull.h"

namespace rc {

/// How near segment a-b comes to a sphere (less its radius: a lower bound for any sphere
/// inside), every object but two kept under the limit: a cylinder of safety's radius. It
/// is `final`, so a traversal that knows its type calls it directly, without a virtual
/// call per sphere (CompleteSearch::clearance).
struct SegmentClearance final : SphereCull {
    /// `stopBelow`: once an object lies nearer than this, stop; `least` is then its distance
    SegmentClearance(const Vec3& from, const Vec3& to, int skip, int skipToo, double cap, double stopBelow)
        : skip(skip), skipToo(skipToo), stopBelow(stopBelow), least(cap) {
        a = from;
        b = to;
        radius = limit = cap;
    }
    /// From the sphere's surface: rc::segmentDistance (tutorial 02's hole) less its radius
    double distance(const Sphere& s) override { return segmentDistance(s.c, a, b) - s.r; }
    void found(int id, double d) override {
        if (id == skip || id == skipToo || !(d < least)) return;
        least = d;
        nearest = id;
        // Below the stop, the search is over: nothing more can meet the limit
        limit = least < stopBelow ? -kNoHit : least;
    }
    int skip, skipToo;
    double stopBelow;
    double least;      ///< the clearance so far (at most the cap)
    int nearest = -1;  ///< the object at that distance (-1: none nearer than the cap)
};

}  // namespace rc
