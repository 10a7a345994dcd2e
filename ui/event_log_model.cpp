#include "event_log_model.h"

#include <algorithm>

#include <QColor>

#include "labels.h"
#include "palette.h"

namespace rcgui {

int EventLogModel::rowsOf(const rc::SessionState* state) {
    if (!state) return 0;
    const rc::TraceRecorder& rec = state->recorder();
    if (reason_ == rc::MissReason::None) return int(missesOnly_ ? rec.misses().size() : rec.events().size());
    // Misses of one reason: found among the misses once, as the log grows
    if (state != state_ || missesScanned_ > rec.misses().size()) {
        ofReason_.clear();
        missesScanned_ = 0;
    }
    for (; missesScanned_ < rec.misses().size(); ++missesScanned_) {
        const std::int32_t i = rec.misses()[missesScanned_];
        const rc::EventRecord& r = rec.events()[std::size_t(i)];
        if (!r.deferred() && r.missReason() == reason_) ofReason_.push_back(i);
    }
    return int(ofReason_.size());
}

void EventLogModel::setState(const rc::SessionState* state) {
    const bool same = state == state_;
    const int total = rowsOf(state);
    const int first = std::max(0, total - kMaxRows);
    if (same && total >= first_ + rows_ && first - first_ < rows_) {
        // The log only grows: the oldest rows leave the window, the new ones join it
        if (first > first_) {
            beginRemoveRows({}, 0, first - first_ - 1);
            rows_ -= first - first_;
            first_ = first;
            endRemoveRows();
        }
        if (total > first_ + rows_) {
            beginInsertRows({}, rows_, total - first_ - 1);
            rows_ = total - first_;
            endInsertRows();
        }
        return;
    }
    beginResetModel();
    state_ = state;
    first_ = first;
    rows_ = total - first;
    endResetModel();
}

void EventLogModel::setMissesOnly(bool on) {
    if (on == missesOnly_) return;
    const rc::SessionState* s = state_;
    missesOnly_ = on;
    state_ = nullptr;
    setState(s);
}

void EventLogModel::setReason(rc::MissReason r) {
    if (r == reason_) return;
    const rc::SessionState* s = state_;
    reason_ = r;
    state_ = nullptr;
    setState(s);
}

int EventLogModel::eventAt(int row) const {
    if (!state_ || row < 0 || row >= rows_) return -1;
    const std::size_t i = std::size_t(first_) + std::size_t(row);
    if (reason_ != rc::MissReason::None) return ofReason_[i];
    return missesOnly_ ? state_->recorder().misses()[i] : int(i);
}

int EventLogModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : rows_; }
int EventLogModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : 7; }

QVariant EventLogModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    static const char* names[] = {"step", "pixel", "path", "kind", "hit", "tests", "decision"};
    return QString(names[section]);
}

QVariant EventLogModel::data(const QModelIndex& index, int role) const {
    const int i = eventAt(index.row());
    if (i < 0) return {};
    const rc::EventRecord& r = state_->recorder().events()[i];
    if (role == Qt::ForegroundRole && index.column() == 6) {
        if (r.deferred() || r.rayDecision() == rc::Decision::Miss) return palette::missReason(r.missReason()).darker(130);
        return {};
    }
    if (role == Qt::ToolTipRole && index.column() == 6) return decisionText(r);
    if (role != Qt::DisplayRole) return {};
    const int w = state_->width();
    switch (index.column()) {
        case 0: return qlonglong(r.step);
        case 1: return QString("%1,%2").arg(r.pixel % w).arg(r.pixel / w);
        case 2: return QString::fromStdString(state_->session().cacheTree().label(r.node));
        case 3: return text(rc::toString(r.rayKind()));
        case 4: return r.deferred() ? QString("?") : objectLabel(state_->scene(), r.hit);
        case 5: return r.tests;
        case 6: return decisionText(r);
    }
    return {};
}

}  // namespace rcgui
