#pragma once
/// \file
/// \brief The radius of a cylinder of safety measured over every object, four at a time.
#include <vector>

#include "geometry/intersection.h"
#include "scene/scene.h"

namespace rc {

/// Every object's bounding sphere in arrays of their own, for CompleteSearch::clearance()
/// in front of the linear scan. A hierarchy finds the few spheres near a segment, but
/// each step of its walk is a branch the processor guesses wrong about as often as right;
/// for a few hundred objects, measuring them all with no branch costs less. The result is
/// the one SegmentClearance would reach, bit for bit: the same operations in the same
/// order, and never an early stop (the exact least distance, which `stopBelow` allows).
class ClearanceScan {
public:
    explicit ClearanceScan(const Scene& scene);
    /// The least distance from segment a-b to any bounding sphere but `skip` and `skipToo`,
    /// at most `cap`; `nearest`, if given, the object at that distance (the lowest id of a
    /// tie; -1 for the cap).
    double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap, int* nearest) const;
    /// The same, one sphere at a time, whatever the processor (for the tests).
    double clearanceScalar(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap, int* nearest) const;
    /// Objects measured (padded to a multiple of four with spheres at infinity).
    std::size_t size() const { return size_; }

private:
    std::size_t size_;
    std::vector<double> x_, y_, z_, r_;  ///< centres and radii by object id, padded
};

}  // namespace rc
