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

#include "search/cache_entry.h"
#include "search/query.h"
#include "search/sample_entries.h"

namespace rc {

/// The ray-tree paths met so far, each with its cache entry. Node 0 is the eye ray (of
/// pixel sample 0); with several pixel samples, sample s has a root path of its own.
/// A path is a chain of steps (kind, light, sample index): shadow ray sample 2 to light 1
/// is a different path from shadow ray sample 0 to light 1.
class CacheTree {
public:
    struct Node {
        int parent = -1;   ///< -1 for the eye paths
        RayKind kind = RayKind::Primary;
        int light = -1;    ///< shadow nodes: which light
        int sample = 0;    ///< which sample of its parent's rays of this kind (pixel sample for eye paths)
        int depth = 1;     ///< the eye ray is depth 1
        int entry = 0;     ///< its cache entry (shared between samples under SampleEntries::Shared)
        std::vector<int> children;
        /// The entries of every path beneath it, so that a flush is one loop, not a walk
        /// of the subtree (a miss in scanline order flushes on every miss)
        std::vector<int> entriesBelow;
    };

    explicit CacheTree(SampleEntries sharing = SampleEntries::PerSample);
    // [cache-tree-child]
    /// The child path of `node` for a ray of `kind` (and `light` for shadows), sample
    /// `sample`; made, with its entry, on first use. Shading says what a ray spawns; the
    /// tree alone decides which entry answers it.
    int child(int node, RayKind kind, int light = -1, int sample = 0);
    /// The eye path of pixel sample `sample` (0: node 0).
    int root(int sample);
    // [cache-tree-child]
    /// Marks every loaded entry beneath `node` as flushed.
    void flushBelow(int node);
    /// Empties every entry (keeps the paths).
    void clear();

    const Node& node(int i) const { return nodes_[i]; }
    CacheEntry& entry(int i) { return entries_[std::size_t(nodes_[i].entry)]; }
    const CacheEntry& entry(int i) const { return entries_[std::size_t(nodes_[i].entry)]; }
    int size() const { return int(nodes_.size()); }
    /// Distinct cache entries (equals size() with one entry per sample).
    int entries() const { return int(entries_.size()); }
    SampleEntries sharing() const { return sharing_; }
    /// Bytes it holds (paths and entries), for the memory a checkpoint takes.
    std::size_t bytes() const;
    /// A readable name such as "eye/reflection/shadow 1" ("#k" marks sample k > 0).
    std::string label(int node) const;

private:
    int make(int parent, RayKind kind, int light, int sample);
    SampleEntries sharing_;
    std::vector<Node> nodes_;
    std::vector<int> roots_;  ///< eye path of each pixel sample met so far
    std::vector<CacheEntry> entries_;
    /// Shared: node -> the node of sample 0 on every step of its path, whose entry it uses
    std::vector<int> canonical_;
};

}  // namespace rc
