#pragma once
/// \file
/// \brief A table model over the recorded trace events, optionally only the misses, or
/// only the misses of one reason.
#include <vector>

#include <QAbstractTableModel>

#include "view/session_state.h"

namespace rcgui {

/// Rows are recorded events (every one, or only misses and deferrals): the newest
/// kMaxRows of them, since a table view keeps a record per row and a render makes
/// millions. Reads the recorder lazily, so rows cost nothing until they are scrolled to.
class EventLogModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;
    /// Follows `state` (null: shows nothing, e.g. while a worker owns the state).
    void setState(const rc::SessionState* state);
    void setMissesOnly(bool on);
    bool missesOnly() const { return missesOnly_; }
    /// Only the committed misses of reason `r` (rc::MissReason::None: no such filter).
    void setReason(rc::MissReason r);
    rc::MissReason reason() const { return reason_; }
    /// The recorder index of a row's event.
    int eventAt(int row) const;
    /// Rows shown at most: the newest events under the filter.
    static constexpr int kMaxRows = 100000;
    /// Events under the filter, shown or not (rowCount() is the newest of them).
    int total() const { return first_ + rows_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    const rc::SessionState* state_ = nullptr;
    bool missesOnly_ = false;
    rc::MissReason reason_ = rc::MissReason::None;
    std::vector<std::int32_t> ofReason_;  ///< with a reason: the events shown, in order
    std::size_t missesScanned_ = 0;       ///< misses() entries ofReason_ has looked at
    int first_ = 0;  ///< events under the filter older than the first row
    int rows_ = 0;
    /// Rows `state` has under the filter (extending ofReason_ to its newest misses).
    int rowsOf(const rc::SessionState* state);
};

}  // namespace rcgui
