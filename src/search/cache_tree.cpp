#include "search/cache_tree.h"

namespace rc {

CacheTree::CacheTree(SampleEntries sharing) : sharing_(sharing) { root(0); }

int CacheTree::make(int parent, RayKind kind, int light, int sample) {
    // [sample-entries]
    // Shared: the path's twin that takes sample 0 at every step lends it its entry (the
    // twin is made first if need be); per sample: an entry of its own
    int twin = -1;
    if (sharing_ == SampleEntries::Shared && (sample != 0 || (parent >= 0 && canonical_[parent] != parent)))
        twin = parent < 0 ? root(0) : child(canonical_[parent], kind, light, 0);
    // [sample-entries]
    Node n;
    n.parent = parent;
    n.kind = kind;
    n.light = light;
    n.sample = sample;
    n.depth = parent < 0 ? 1 : nodes_[parent].depth + 1;
    const int id = int(nodes_.size());
    if (twin >= 0) {
        n.entry = nodes_[twin].entry;
    } else {
        n.entry = int(entries_.size());
        entries_.emplace_back();
    }
    canonical_.push_back(twin >= 0 ? twin : id);
    const int entry = n.entry;
    nodes_.push_back(std::move(n));
    if (parent >= 0) nodes_[parent].children.push_back(id);
    for (int up = parent; up >= 0; up = nodes_[up].parent) nodes_[up].entriesBelow.push_back(entry);
    return id;
}

int CacheTree::root(int sample) {
    if (sample < int(roots_.size()) && roots_[sample] >= 0) return roots_[sample];
    if (sample >= int(roots_.size())) roots_.resize(std::size_t(sample) + 1, -1);
    const int id = make(-1, RayKind::Primary, -1, sample);
    roots_[sample] = id;
    return id;
}

int CacheTree::child(int node, RayKind kind, int light, int sample) {
    for (int c : nodes_[node].children)
        if (nodes_[c].kind == kind && nodes_[c].light == light && nodes_[c].sample == sample) return c;
    return make(node, kind, light, sample);
}

void CacheTree::flushBelow(int node) {
    // [flush-below]
    // A miss at a parent: the rays of the paths beneath now start somewhere else
    // (arithmetic, not a branch: whether an entry below is loaded is a coin toss; Loaded
    // is Flushed + 1)
    static_assert(int(CacheEntry::State::Loaded) == int(CacheEntry::State::Flushed) + 1);
    for (int k : nodes_[node].entriesBelow) {
        CacheEntry::State& s = entries_[std::size_t(k)].state;
        s = CacheEntry::State(std::uint8_t(s) - std::uint8_t(s == CacheEntry::State::Loaded));
    }
    // [flush-below]
}

void CacheTree::clear() {
    for (CacheEntry& e : entries_) e = {};
}

std::string CacheTree::label(int node) const {
    const Node& n = nodes_[node];
    std::string me(n.parent < 0 ? std::string_view("eye") : toString(n.kind));
    if (n.kind == RayKind::Shadow) me.append(" ").append(std::to_string(n.light + 1));
    if (n.sample > 0) me.append(" #").append(std::to_string(n.sample));
    return n.parent < 0 ? me : label(n.parent).append("/").append(me);
}

std::size_t CacheTree::bytes() const {
    std::size_t b = nodes_.size() * sizeof(Node) + entries_.size() * sizeof(CacheEntry) +
                    (roots_.size() + canonical_.size()) * sizeof(int);
    for (const Node& n : nodes_) b += (n.children.size() + n.entriesBelow.size()) * sizeof(int);
    return b;
}

}  // namespace rc
