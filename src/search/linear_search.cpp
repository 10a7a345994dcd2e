#include "search/linear_search.h"

#include "search/bounding_volume_hierarchy.h"
#include "search/clearance_scan.h"
#include "search/sphere_batch.h"
#include "search/standard_algorithm.h"

namespace rc {

double LinearSearch::clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                               double stopBelow, int* nearest) const {
#ifndef RAYCACHE_STUDENT
    // [clearance-by-scan]
    // A few hundred objects: every one measured, four at a time, costs less than walking
    // the hierarchy (a student build measures with the student's rc::segmentDistance)
    if (scan_) return scan_->clearance(a, b, skip, skipToo, cap, nearest);
    // [clearance-by-scan]
#endif
    if (regions_) return regions_->clearance(a, b, skip, skipToo, cap, stopBelow, nearest);
    return CompleteSearch::clearance(a, b, skip, skipToo, cap, stopBelow, nearest);
}

void LinearSearch::cull(SphereCull& c) const {
    if (regions_) {
        regions_->cull(c);
    } else {
        CompleteSearch::cull(c);
    }
}

LinearSearch::LinearSearch(const Scene& scene, Regions regions) : CompleteSearch(scene) {
    auto all = std::make_unique<SphereBatch>();
    for (int id = 0; id < scene.size(); ++id) all->add(scene, id);
    all_ = std::move(all);
    if (regions == Regions::Hierarchy) regions_ = std::make_unique<const BoundingVolumeHierarchy>(scene);
    if (scene.size() <= kClearanceScanLimit) scan_ = std::make_unique<const ClearanceScan>(scene);
}

LinearSearch::~LinearSearch() = default;

Answer LinearSearch::nearest(const Query& q, Counters& n) const {
#ifdef RAYCACHE_STUDENT
    return standardAlgorithm(scene_, q, n);  // tutorial 01: the student's loop, same answers and counts
#endif
    // [linear-search]
    // Test every object; keep the nearest hit in front of tmax
    Answer best;
    all_->testAll(scene_, q, best, n);
    return best;
    // [linear-search]
}

}  // namespace rc
