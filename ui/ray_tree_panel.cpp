#include "ray_tree_panel.h"

#include <map>

#include <QHeaderView>
#include <QTreeWidgetItemIterator>

#include "labels.h"

namespace rcgui {

RayTreePanel::RayTreePanel(QWidget* parent) : QTreeWidget(parent) {
    setHeaderLabels({"ray (path)", "kind", "hit", "decision", "tests", "step"});
    setAlternatingRowColors(true);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (item) emit rayChosen(item->data(0, Qt::UserRole).toInt());
    });
}

void RayTreePanel::showPixel(const rc::SessionState* state, int pixel) {
    const QSignalBlocker block(this);
    clear();
    pixel_ = pixel;
    if (!state || pixel < 0) return;
    const rc::CacheTree& paths = state->session().cacheTree();
    std::map<int, QTreeWidgetItem*> byNode;  // committed ray of each path
    for (int i : state->recorder().eventsOf(pixel)) {
        const rc::EventRecord& r = state->recorder().events()[i];
        const int parentNode = paths.node(r.node).parent;
        auto parentIt = byNode.find(parentNode);
        auto* item = parentIt != byNode.end() ? new QTreeWidgetItem(parentIt->second) : new QTreeWidgetItem(this);
        item->setText(0, QString::fromStdString(paths.label(r.node)));
        item->setText(1, text(rc::toString(r.rayKind())));
        item->setText(2, r.deferred() ? QString("?") : objectLabel(state->scene(), r.hit));
        item->setText(3, decisionText(r));
        item->setText(4, QString::number(r.tests));
        item->setText(5, QString::number(r.step));
        item->setData(0, Qt::UserRole, i);
        if (r.deferred()) item->setForeground(3, QColor(200, 40, 60));
        else if (r.rayDecision() == rc::Decision::Miss) item->setForeground(3, QColor(220, 100, 0));
        if (!r.deferred()) byNode[r.node] = item;
    }
    expandAll();
}

}  // namespace rcgui

namespace rcgui {

void RayTreePanel::setCurrentEvent(int event) {
    const QSignalBlocker block(this);
    for (QTreeWidgetItemIterator it(this); *it; ++it)
        if ((*it)->data(0, Qt::UserRole).toInt() == event) {
            setCurrentItem(*it);
            scrollToItem(*it);
            return;
        }
}

}  // namespace rcgui
