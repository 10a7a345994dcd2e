#include "search/cache_tree.h"

namespace rc {

CacheTree::CacheTree() { nodes_.push_back({}); }

int CacheTree::child(int node, RayKind kind, int light) {
    for (int c : nodes_[node].children)
        if (nodes_[c].kind == kind && nodes_[c].light == light) return c;
    Node n;
    n.parent = node;
    n.kind = kind;
    n.light = light;
    n.depth = nodes_[node].depth + 1;
    nodes_.push_back(n);
    const int id = int(nodes_.size()) - 1;
    nodes_[node].children.push_back(id);
    return id;
}

void CacheTree::flushBelow(int node) {
    // [flush-below]
    // A miss at a parent: the children's rays now start somewhere else
    for (int c : nodes_[node].children) {
        CacheEntry& e = nodes_[c].entry;
        if (e.state == CacheEntry::State::Loaded) e.state = CacheEntry::State::Flushed;
        flushBelow(c);
    }
    // [flush-below]
}

void CacheTree::clear() {
    for (Node& n : nodes_) n.entry = {};
}

std::string CacheTree::label(int node) const {
    if (node == 0) return "eye";
    const Node& n = nodes_[node];
    std::string me(toString(n.kind));
    if (n.kind == RayKind::Shadow) me += " " + std::to_string(n.light + 1);
    return label(n.parent) + "/" + me;
}

}  // namespace rc
