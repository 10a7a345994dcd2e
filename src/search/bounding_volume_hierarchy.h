#pragma once
/// \file
/// \brief A bounding volume hierarchy (Rubin and Whitted 1980, "a hierarchical tree of
/// bounding boxes"): a complete search that opens only the boxes a ray enters, and answers
/// the caches' culling queries (blocker hulls, cylinders of safety, empty cones) by the
/// bounding spheres of the same tree.
#include <memory>
#include <vector>

#include "search/complete_search.h"

namespace rc {

class SphereBatch;

/// A binary tree over the objects, split by the surface area heuristic. Each node holds
/// an axis-aligned box (for rays) and a sphere around its objects' bounding spheres (for
/// the caches' queries). Returns exactly what LinearSearch returns, ties included: a box
/// is skipped only when the ray enters it beyond the nearest hit known, and boxes are
/// widened by a few ulps of the scene so rounding never loses an object.
class BoundingVolumeHierarchy final : public CompleteSearch {
public:
    explicit BoundingVolumeHierarchy(const Scene& scene);
    ~BoundingVolumeHierarchy() override;
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "bvh"; }
    /// Descends only into nodes whose bounding sphere meets `c`.
    void cull(SphereCull& c) const override { cullWith(c); }
    /// The same for a cull whose type is known here: a `final` one is measured without a
    /// virtual call per sphere (a cylinder of safety measures a hundred-odd).
    template <class Cull>
    void cullWith(Cull& c) const;
    double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                     double stopBelow = -kNoHit, int* nearest = nullptr) const override;
    /// Inner nodes and leaves.
    int nodeCount() const { return int(nodes_.size() + leaves_.size()); }
    /// The deepest leaf (the root is depth 1).
    int depth() const;

private:
    static constexpr int kMaxDepth = 60;  ///< the traversal stack holds this many nodes
    /// A child: an inner node (>= 0) or a leaf (~index into leaves_, < 0).
    using Ref = int;
    struct Box {
        double lo[3], hi[3];
    };
    /// An inner node keeps both children's boxes, so one visit tests both from one place.
    struct Node {
        Box box[2];
        Ref child[2];
    };
    /// A leaf: objects order_[first, first + count).
    struct Leaf {
        int first, count;
    };
    /// Builds the subtree of ids[begin, end) and sets `box` to its box; returns its ref.
    Ref build(std::vector<int>& ids, int begin, int end, const std::vector<double>& boxes, int depth, Box& box);
    const Sphere& bound(Ref r) const { return r >= 0 ? nodeBounds_[r] : leafBounds_[~r]; }
    std::vector<Node> nodes_;
    std::vector<Leaf> leaves_;
    /// Per node and per leaf: a sphere holding its objects' bounding spheres
    std::vector<Sphere> nodeBounds_, leafBounds_;
    Ref root_ = 0;
    Box rootBox_{};
    std::vector<int> order_;      ///< object ids in leaf order
    /// The same objects, stored for the ray loop (search/sphere_batch.h, which tests objects
    /// and so holds solution regions, is included only by the sources that test)
    std::unique_ptr<SphereBatch> leaf_;
    double pad_ = 0.0;
    int depth_ = 0;
};

template <class Cull>
void BoundingVolumeHierarchy::cullWith(Cull& c) const {
    if (order_.empty()) return;
    // [bvh-cull]
    // Open the bounding spheres within the limit, nearest first; the limit may shrink
    Ref stack[kMaxDepth + 2];
    double distances[kMaxDepth + 2];
    int top = 0;
    stack[top] = root_;
    distances[top++] = c.distance(bound(root_));
    while (top > 0) {
        --top;
        if (distances[top] > c.limit) continue;
        if (stack[top] < 0) {
            const Leaf& leaf = leaves_[~stack[top]];
            for (int i = leaf.first; i < leaf.first + leaf.count; ++i) {
                const double d = c.distance(scene_.objects[order_[i]].bound);
                if (d <= c.limit) c.found(order_[i], d);
            }
            continue;
        }
        const Node& node = nodes_[stack[top]];
        const double dl = c.distance(bound(node.child[0])), dr = c.distance(bound(node.child[1]));
        const int nearer = dl <= dr ? 0 : 1;
        stack[top] = node.child[1 - nearer];
        distances[top++] = nearer == 0 ? dr : dl;
        stack[top] = node.child[nearer];
        distances[top++] = nearer == 0 ? dl : dr;
    }
    // [bvh-cull]
}

}  // namespace rc
