#include "cache_tree_panel.h"

#include <cmath>
#include <vector>

#include <QHeaderView>

#include "labels.h"
#include "palette.h"

namespace rcgui {

CacheTreePanel::CacheTreePanel(QWidget* parent) : QTreeWidget(parent) {
    // What a lecture reads first comes first: the step (the tree's indentation gives the
    // rest of the path), whether the entry is loaded or flushed, what it holds
    setHeaderLabels({"path", "state", "object", "holds", "origin"});
    setIndentation(14);
    setAlternatingRowColors(true);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
}

void CacheTreePanel::refresh(const rc::SessionState* state, int focusNode) {
    if (!state) return;
    const rc::CacheTree& tree = state->session().cacheTree();
    const rc::BlockerLists* lists = state->session().strategy().blockerLists();
    const rc::Scene& scene = state->scene();
    // Reuse items so the scroll position and expansion survive a refresh
    std::vector<QTreeWidgetItem*> items(tree.size(), nullptr);
    for (int i = 0; i < tree.size(); ++i) {
        const auto& node = tree.node(i);
        QTreeWidgetItem* parent = node.parent >= 0 ? items[node.parent] : nullptr;
        QTreeWidgetItem* item = nullptr;
        // Find an existing item for this node
        const int count = parent ? parent->childCount() : topLevelItemCount();
        for (int k = 0; k < count && !item; ++k) {
            QTreeWidgetItem* c = parent ? parent->child(k) : topLevelItem(k);
            if (c->data(0, Qt::UserRole).toInt() == i) item = c;
        }
        if (!item) {
            item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(this);
            item->setData(0, Qt::UserRole, i);
            item->setExpanded(true);
        }
        items[i] = item;
        const rc::CacheEntry& e = tree.entry(i);
        // The step this node adds to its parent's path; the whole path in the tooltip
        const QString path = QString::fromStdString(tree.label(i));
        item->setText(0, path.section('/', -1));
        item->setToolTip(0, path);
        const bool flushed = e.state == rc::CacheEntry::State::Flushed;
        item->setText(1, e.state == rc::CacheEntry::State::Loaded ? "loaded" : flushed ? "flushed" : "empty");
        item->setText(4, e.origin.object < 0 ? QString("eye") : objectLabel(scene, e.origin.object) + (e.origin.inside ? " (inside)" : ""));
        item->setText(2, e.state == rc::CacheEntry::State::Empty ? QString() : objectLabel(scene, e.object));
        // A flush shows: the flushed entries in the flushed-miss colour, the focused ray's bold
        for (int c = 0; c < columnCount(); ++c) {
            item->setBackground(c, flushed ? QBrush(palette::missReason(rc::MissReason::Flushed).darker(170)) : QBrush());
            QFont f = item->font(c);
            f.setBold(i == focusNode);
            item->setFont(c, f);
        }
        QString holds;
        // The list of the entry's pair: its origin and its object (a shadow entry: its light).
        // On a tiled polygon the lists are kept per tile, and found from the ray (overlays).
        const int target = node.kind == rc::RayKind::Shadow ? (lists ? lists->lightSite(node.light) : -1) : e.object;
        if (lists && e.state != rc::CacheEntry::State::Empty && target >= 0) {
            const std::vector<int>* l = lists->find(lists->originSite(e.origin), target);
            holds = l ? QString("blocker list: %1").arg(int(l->size())) : QString("blocker list: built when next used");
            if (l && !l->empty()) {
                QStringList ids;
                for (std::size_t k = 0; k < l->size() && k < 8; ++k) ids << QString::number((*l)[k]);
                holds += " [" + ids.join(' ') + (l->size() > 8 ? " …]" : "]");
            }
        } else if (e.cylinder.radius >= 0.0) {
            holds = QString("cylinder R = %1").arg(e.cylinder.radius, 0, 'g', 4);
        } else if (e.coneAngle >= 0.0) {
            holds = QString("empty cone %1°").arg(e.coneAngle * 180.0 / M_PI, 0, 'g', 3);
        } else if (e.pending && e.state == rc::CacheEntry::State::Loaded) {
            // A cylinder is measured only once a ray may fit in it
            holds = e.cylinderBelow < rc::kNoHit
                        ? QString("cylinder R < %1, not measured yet").arg(e.cylinderBelow, 0, 'g', 4)
                        : QString("built when next used");
        }
        item->setText(3, holds);
    }
}

}  // namespace rcgui
