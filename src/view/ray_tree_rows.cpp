#include "view/ray_tree_rows.h"

#include <map>

#include "view/event_text.h"

namespace rc {

std::vector<RayTreeRow> rayTreeRows(const SessionState& s, int pixel) {
    std::vector<RayTreeRow> rows;
    if (pixel < 0 || pixel >= s.recorder().width() * s.recorder().height()) return rows;
    const CacheTree& paths = s.session().cacheTree();
    std::map<int, int> rowOfNode;  // the committed ray of each path: the parent of its children
    for (int i : s.recorder().eventsOf(pixel)) {
        const EventRecord r = s.recorder().events()[std::size_t(i)];
        RayTreeRow row;
        row.event = i;
        const auto parent = rowOfNode.find(paths.node(r.node).parent);
        if (parent != rowOfNode.end()) {
            row.parent = parent->second;
            row.depth = rows[std::size_t(parent->second)].depth + 1;
        }
        row.path = paths.label(r.node);
        row.kind = toString(r.rayKind());
        row.deferred = r.deferred();
        row.miss = !row.deferred && r.rayDecision() == Decision::Miss;
        row.hit = row.deferred ? "?" : objectLabel(s.scene(), r.hit);
        row.decision = decisionText(r);
        row.tests = r.tests;
        row.step = r.step;
        if (!row.deferred) rowOfNode[r.node] = int(rows.size());
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace rc
