#include "event_log_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableView>
#include <QVBoxLayout>

#include "event_log_model.h"
#include "labels.h"

namespace rcgui {

EventLogPanel::EventLogPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    missesOnly_ = new QCheckBox("Misses only", this);
    follow_ = new QCheckBox("Follow", this);
    follow_->setChecked(true);
    reason_ = new QComboBox(this);
    reason_->addItem("any reason", int(rc::MissReason::None));
    for (int r = 1; r < rc::kMissReasons; ++r) reason_->addItem(text(rc::toString(rc::MissReason(r))), r);
    reason_->setToolTip("Only the misses of this reason, here and for Next miss (M)");
    row->addWidget(missesOnly_);
    row->addWidget(reason_);
    row->addWidget(follow_);
    shown_ = new QLabel(this);
    shown_->setToolTip("The log keeps the newest rays; Misses only, a reason, or Go to step reach older ones");
    shown_->hide();
    row->addWidget(shown_);
    row->addStretch(1);
    layout->addLayout(row);
    model_ = new EventLogModel(this);
    table_ = new QTableView(this);
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(table_, 1);
    connect(missesOnly_, &QCheckBox::toggled, this, &EventLogPanel::setMissesOnly);
    connect(reason_, &QComboBox::activated, this, [this](int i) {
        const auto r = rc::MissReason(reason_->itemData(i).toInt());
        setReason(r);
        emit reasonChosen(r);
    });
    connect(table_, &QTableView::activated, this, [this](const QModelIndex& i) {
        const int e = model_->eventAt(i.row());
        if (e >= 0) emit eventChosen(e);
    });
    connect(table_, &QTableView::clicked, this, [this](const QModelIndex& i) {
        const int e = model_->eventAt(i.row());
        if (e >= 0) emit eventChosen(e);
    });
}

void EventLogPanel::setMissesOnly(bool on) {
    if (missesOnly_->isChecked() != on) missesOnly_->setChecked(on);
    model_->setMissesOnly(on);
}

void EventLogPanel::setReason(rc::MissReason r) {
    reason_->setCurrentIndex(std::max(0, reason_->findData(int(r))));
    model_->setReason(r);
}

void EventLogPanel::refresh(const rc::SessionState* state) {
    model_->setState(state);
    shown_->setVisible(model_->total() > model_->rowCount());
    if (shown_->isVisible())
        shown_->setText(QString("newest %1 of %2").arg(QLocale().toString(model_->rowCount()),
                                                      QLocale().toString(model_->total())));
    if (follow_->isChecked() && model_->rowCount() > 0) table_->scrollToBottom();
}

}  // namespace rcgui
