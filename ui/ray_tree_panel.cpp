#include "ray_tree_panel.h"

#include <QHeaderView>
#include <QTreeWidgetItemIterator>

#include "labels.h"
#include "palette.h"
#include "view/ray_tree_rows.h"

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
    // The core's rows (rc::rayTreeRows), as the page's
    std::vector<QTreeWidgetItem*> items;
    for (const rc::RayTreeRow& r : rc::rayTreeRows(*state, pixel)) {
        auto* item = r.parent >= 0 ? new QTreeWidgetItem(items[std::size_t(r.parent)]) : new QTreeWidgetItem(this);
        item->setText(0, text(r.path));
        item->setText(1, text(r.kind));
        item->setText(2, text(r.hit));
        item->setText(3, text(r.decision));
        item->setText(4, QString::number(r.tests));
        item->setText(5, QString::number(r.step));
        item->setData(0, Qt::UserRole, r.event);
        if (r.deferred) item->setForeground(3, palette::qt(rc::colours::kDeferredText));
        else if (r.miss) item->setForeground(3, palette::qt(rc::colours::kMissText));
        items.push_back(item);
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
