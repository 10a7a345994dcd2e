#include "search/bounding_volume_hierarchy.h"
#include "search/sphere_batch.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "search/segment_clearance.h"

namespace rc {

namespace {
constexpr int kBins = 12;
constexpr int kMaxLeaf = 8;

double area(const double* lo, const double* hi) {
    const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x * y + y * z + z * x;
}

void grow(double* lo, double* hi, const double* box) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], box[k]);
        hi[k] = std::max(hi[k], box[3 + k]);
    }
}

/// Where the ray enters the box within [0, limit], or -1 if it does not. A zero
/// direction component gives 0 * inf = NaN, which the min/max below ignore: the slab
/// counts as entered, which can only open more boxes.
[[gnu::always_inline]] inline double entry(const double* lo, const double* hi, const Vec3& o, const double* inv, double limit) {
    double t0 = 0.0, t1 = limit;
    for (int k = 0; k < 3; ++k) {
        const double a = (lo[k] - o[k]) * inv[k], b = (hi[k] - o[k]) * inv[k];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    return t0 <= t1 ? t0 : -1.0;
}
}  // namespace

BoundingVolumeHierarchy::BoundingVolumeHierarchy(const Scene& scene)
    : CompleteSearch(scene), leaf_(std::make_unique<SphereBatch>()) {
    if (scene.size() == 0) return;
    // Boxes widened by a few ulps of the scene: rounding in the slab test never loses a hit
    pad_ = 1e-9 * scene.extent() + 1e-300;
    std::vector<double> boxes(6 * std::size_t(scene.size()));
    for (int id = 0; id < scene.size(); ++id) {
        const Object& o = scene.objects[id];
        double* box = &boxes[6 * std::size_t(id)];
        Vec3 lo = o.bound.c - Vec3(o.bound.r), hi = o.bound.c + Vec3(o.bound.r);
        if (o.shape == Shape::Polygon) {  // a polygon's own box is tighter than its sphere's
            lo = hi = scene.polygons[o.index].vertices.front();
            for (const Vec3& v : scene.polygons[o.index].vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
        }
        if (o.shape == Shape::Cone) boundingBox(scene.cones[o.index], lo, hi);  // so is a cone's
        for (int k = 0; k < 3; ++k) {
            box[k] = lo[k] - pad_;
            box[3 + k] = hi[k] + pad_;
        }
    }
    std::vector<int> ids(std::size_t(scene.size()));
    for (int id = 0; id < scene.size(); ++id) ids[id] = id;
    root_ = build(ids, 0, int(ids.size()), boxes, 1, rootBox_);
    order_ = ids;
    for (int id : order_) leaf_->add(scene, id);
}

BoundingVolumeHierarchy::~BoundingVolumeHierarchy() = default;

BoundingVolumeHierarchy::Ref BoundingVolumeHierarchy::build(std::vector<int>& ids, int begin, int end,
                                                            const std::vector<double>& boxes, int depth, Box& node) {
    depth_ = std::max(depth_, depth);
    // The node's box, its centroids' box, and a sphere around its objects' spheres
    double clo[3], chi[3];
    for (int k = 0; k < 3; ++k) {
        node.lo[k] = clo[k] = kNoHit;
        node.hi[k] = chi[k] = -kNoHit;
    }
    auto centroid = [&](int id, int k) { return 0.5 * (boxes[6 * id + k] + boxes[6 * id + 3 + k]); };
    Vec3 slo(kNoHit), shi(-kNoHit);
    for (int i = begin; i < end; ++i) {
        grow(node.lo, node.hi, &boxes[6 * ids[i]]);
        for (int k = 0; k < 3; ++k) {
            clo[k] = std::min(clo[k], centroid(ids[i], k));
            chi[k] = std::max(chi[k], centroid(ids[i], k));
        }
        const Sphere& s = scene_.objects[ids[i]].bound;
        slo = glm::min(slo, s.c - Vec3(s.r));
        shi = glm::max(shi, s.c + Vec3(s.r));
    }
    // The bounding sphere: around the spheres' box, as large as the farthest sphere needs
    Sphere bound{0.5 * (slo + shi), 0.0};
    for (int i = begin; i < end; ++i) {
        const Sphere& s = scene_.objects[ids[i]].bound;
        bound.r = std::max(bound.r, glm::length(s.c - bound.c) + s.r);
    }
    bound.r = bound.r * (1.0 + 1e-12) + pad_;

    // [bvh-split]
    // Split where the surface area heuristic says, over binned centroids on the widest axis
    const int count = end - begin;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    const double span = chi[axis] - clo[axis];
    int split = -1;
    if (count > 2 && span > 0.0 && depth < kMaxDepth) {
        std::array<int, kBins> binCount{};
        std::array<std::array<double, 6>, kBins> binBox;
        for (auto& b : binBox) b = {kNoHit, kNoHit, kNoHit, -kNoHit, -kNoHit, -kNoHit};
        auto binOf = [&](int id) {
            return std::min(kBins - 1, int(kBins * (centroid(id, axis) - clo[axis]) / span));
        };
        for (int i = begin; i < end; ++i) {
            const int b = binOf(ids[i]);
            ++binCount[b];
            grow(&binBox[b][0], &binBox[b][3], &boxes[6 * ids[i]]);
        }
        // Cost of each cut, in units of one object test; a box test costs one too
        const double parent = std::max(area(node.lo, node.hi), 1e-300);
        double bestCost = count <= kMaxLeaf ? double(count) : kNoHit;
        for (int cut = 1; cut < kBins; ++cut) {
            double llo[3] = {kNoHit, kNoHit, kNoHit}, lhi[3] = {-kNoHit, -kNoHit, -kNoHit};
            double rlo[3] = {kNoHit, kNoHit, kNoHit}, rhi[3] = {-kNoHit, -kNoHit, -kNoHit};
            int nl = 0, nr = 0;
            for (int b = 0; b < kBins; ++b) {
                if (binCount[b] == 0) continue;
                if (b < cut) { grow(llo, lhi, binBox[b].data()); nl += binCount[b]; }
                else { grow(rlo, rhi, binBox[b].data()); nr += binCount[b]; }
            }
            if (nl == 0 || nr == 0) continue;
            const double cost = 1.0 + (nl * area(llo, lhi) + nr * area(rlo, rhi)) / parent;
            if (cost < bestCost) {
                bestCost = cost;
                split = cut;
            }
        }
        if (split > 0) {
            const auto mid = std::partition(ids.begin() + begin, ids.begin() + end,
                                            [&](int id) { return binOf(id) < split; });
            split = int(mid - ids.begin());
        }
    } else if (count > kMaxLeaf && depth < kMaxDepth) {
        split = begin + count / 2;  // every centroid in one place: halve the list
    }
    // [bvh-split]
    // A leaf, or an inner node and its two children
    if (split < 0) {
        leaves_.push_back({begin, count});
        leafBounds_.push_back(bound);
        return ~Ref(leaves_.size() - 1);
    }
    const Ref index = Ref(nodes_.size());
    nodes_.emplace_back();
    nodeBounds_.push_back(bound);
    Node inner;
    inner.child[0] = build(ids, begin, split, boxes, depth + 1, inner.box[0]);
    inner.child[1] = build(ids, split, end, boxes, depth + 1, inner.box[1]);
    nodes_[index] = inner;
    return index;
}

Answer BoundingVolumeHierarchy::nearest(const Query& q, Counters& n) const {
    Answer best;
    if (order_.empty()) return best;
    const Vec3& o = q.ray.o;
    const double inv[3] = {1.0 / q.ray.d.x, 1.0 / q.ray.d.y, 1.0 / q.ray.d.z};
    // [bvh-traverse]
    // Open the boxes the ray enters before the nearest hit so far, nearer child first
    Ref stack[kMaxDepth + 2];
    double enters[kMaxDepth + 2];
    int top = 0;
    const double t = entry(rootBox_.lo, rootBox_.hi, o, inv, q.tmax);
    if (t < 0.0) return best;
    stack[top] = root_;
    enters[top++] = t;
    while (top > 0) {
        // A box entered beyond the nearest hit cannot hold a nearer one (nor an equal one:
        // boxes are widened, so a hit at t lies inside its box before t)
        --top;
        const double limit = std::min(best.t, q.tmax);
        if (enters[top] > limit) continue;  // the nearest hit moved in front of it
        if (stack[top] < 0) {
            const Leaf& leaf = leaves_[~stack[top]];
            leaf_->test(scene_, q, std::size_t(leaf.first), std::size_t(leaf.first + leaf.count), best, n);
            continue;
        }
        const Node& node = nodes_[stack[top]];
        const double tl = entry(node.box[0].lo, node.box[0].hi, o, inv, limit);
        const double tr = entry(node.box[1].lo, node.box[1].hi, o, inv, limit);
        // Push the farther child first, so the nearer is opened next
        const int nearer = tl <= tr ? 0 : 1;
        const double tNear = nearer == 0 ? tl : tr, tFar = nearer == 0 ? tr : tl;
        if (tFar >= 0.0) {
            stack[top] = node.child[1 - nearer];
            enters[top++] = tFar;
        }
        if (tNear >= 0.0) {
            stack[top] = node.child[nearer];
            enters[top++] = tNear;
        }
    }
    // [bvh-traverse]
    return best;
}

double BoundingVolumeHierarchy::clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                                          double stopBelow, int* nearest) const {
    SegmentClearance c(a, b, skip, skipToo, cap, stopBelow);
    cullWith(c);
    if (nearest) *nearest = c.nearest;
    return c.least;
}

int BoundingVolumeHierarchy::depth() const { return depth_; }

}  // namespace rc
