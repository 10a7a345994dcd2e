#pragma once
/// \file
/// \brief A bounding volume hierarchy (Rubin and Whitted 1980, "a hierarchical tree of
/// bounding boxes"): a complete search that opens only the boxes a ray enters, and answers
/// the caches' culling queries (blocker hulls, cylinders of safety, empty cones) by the
/// bounding spheres of the same tree.
#include <vector>

#include "search/complete_search.h"

namespace rc {

/// A binary tree over the objects, split by the surface area heuristic. Each node holds
/// an axis-aligned box (for rays) and a sphere around its objects' bounding spheres (for
/// the caches' queries). Returns exactly what LinearSearch returns, ties included: a box
/// is skipped only when the ray enters it beyond the nearest hit known, and boxes are
/// widened by a few ulps of the scene so rounding never loses an object.
class BoundingVolumeHierarchy final : public CompleteSearch {
public:
    explicit BoundingVolumeHierarchy(const Scene& scene);
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "bvh"; }
    /// Descends only into nodes whose bounding sphere meets `c`.
    void cull(SphereCull& c) const override;
    int nodeCount() const { return int(nodes_.size()); }
    /// The deepest leaf (the root is depth 1).
    int depth() const;

private:
    /// A node: `count` > 0 is a leaf of objects order_[first, first + count); otherwise
    /// its children are the next node and node `first`.
    struct Node {
        double lo[3], hi[3];
        int first = 0;
        int count = 0;
    };
    int build(std::vector<int>& ids, int begin, int end, const std::vector<double>& boxes, int depth);
    std::vector<Node> nodes_;
    std::vector<Sphere> bounds_;  ///< per node: a sphere holding its objects' bounding spheres
    std::vector<int> order_;      ///< object ids in leaf order
    SphereBatch leaf_;            ///< the same objects, stored for the ray loop
    double pad_ = 0.0;
    int depth_ = 0;
};

}  // namespace rc
