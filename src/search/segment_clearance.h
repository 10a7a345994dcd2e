#pragma once
/// \file
/// \brief How near a segment comes to the objects: the radius of a cylinder of safety.
#include <algorithm>

#include <glm/geometric.hpp>

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
        : ab(to - from), skip(skip), skipToo(skipToo), stopBelow(stopBelow), least(cap) {
        a = from;
        b = to;
        // BEGIN SOLUTION 02
        const double len2 = glm::dot(ab, ab);
        invLen2 = len2 > 0.0 ? 1.0 / len2 : 0.0;
        // END SOLUTION
        // BEGIN STUB
        // invLen2 = 0.0;  // not used: distance() asks rc::segmentDistance in this edition
        // END STUB
        radius = limit = cap;
    }
    /// From the sphere's surface: the distance to the segment less the sphere's radius. The
    /// instructor's build measures it inline, with the segment's inverse squared length
    /// kept, since every sphere the cull reaches is measured; the student edition, where
    /// tutorial 02 is open, calls the student's rc::segmentDistance instead.
    double distance(const Sphere& s) override {
        // BEGIN SOLUTION 02
        const Vec3 p = s.c - a;
        const double t = std::clamp(glm::dot(p, ab) * invLen2, 0.0, 1.0);
        return glm::length(p - t * ab) - s.r;
        // END SOLUTION
        // BEGIN STUB
        // return segmentDistance(s.c, a, b) - s.r;
        // END STUB
    }
    void found(int id, double d) override {
        if (id == skip || id == skipToo || !(d < least)) return;
        least = d;
        nearest = id;
        // Below the stop, the search is over: nothing more can meet the limit
        limit = least < stopBelow ? -kNoHit : least;
    }
    Vec3 ab;         ///< b - a
    double invLen2;  ///< 1 / |b - a|^2 (0 for a point)
    int skip, skipToo;
    double stopBelow;
    double least;      ///< the clearance so far (at most the cap)
    int nearest = -1;  ///< the object at that distance (-1: none nearer than the cap)
};

}  // namespace rc
