#pragma once
/// \file
/// \brief The cache tree: one cache entry per ray-tree path, mirroring the ray tree.
///
/// "The cache should be organized as a tree. There is little reason to suspect that a
/// reflected ray will hit the same object as the refracted ray or the incident ray"
/// (Hanrahan 1986). A node is a path such as eye, eye->reflection, eye->shadow to light 1;
/// a miss at a node flushes the entries beneath it.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/safety_cylinder.h"
#include "search/query.h"

namespace rc {

/// What a cache entry holds. The strategies use the fields they need: the cylinder
/// cache the segment and its cylinder of safety; the blocker cache the object hit and
/// (through BlockerLists) its potential blockers, a cylinder for rays that hit nothing,
/// and an empty cone for eye rays that hit nothing.
struct CacheEntry {
    enum class State : std::uint8_t { Empty, Flushed, Loaded };
    State state = State::Empty;
    RayOrigin origin;          ///< the entry answers rays leaving this origin only
    int object = -1;           ///< the object last hit, -1 for nothing
    SafetyCylinder cylinder;   ///< around the last segment (radius < 0: none)
    Vec3 coneAxis{0.0};        ///< empty cone around the last empty eye ray
    double coneAngle = -1.0;   ///< its half-angle in radians (< 0: none)
    double coneCos = 2.0;      ///< cos(coneAngle), for the test without trigonometry
    double coneSin = 0.0;      ///< sin(coneAngle)
    bool pending = false;      ///< cylinder or cone not built yet: built when the entry is next used
    int blockerOrigin = -1;    ///< the site pair of the blocker list in use (for display)
    int blockerTarget = -1;
};

/// The ray-tree paths met so far, each with its cache entry. Node 0 is the eye ray.
class CacheTree {
public:
    struct Node {
        int parent = -1;
        RayKind kind = RayKind::Primary;
        int light = -1;  ///< shadow nodes: which light
        int depth = 1;   ///< the eye ray is depth 1
        std::vector<int> children;
        CacheEntry entry;
    };

    CacheTree();
    /// The child path of `node` for a ray of `kind` (and `light` for shadows); made on first use.
    int child(int node, RayKind kind, int light = -1);
    /// Marks every loaded entry beneath `node` as flushed.
    void flushBelow(int node);
    /// Empties every entry (keeps the paths).
    void clear();

    const Node& node(int i) const { return nodes_[i]; }
    CacheEntry& entry(int i) { return nodes_[i].entry; }
    int size() const { return int(nodes_.size()); }
    /// A readable name such as "eye/reflection/shadow 1".
    std::string label(int node) const;

private:
    std::vector<Node> nodes_;
};

}  // namespace rc
