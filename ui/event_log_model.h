#pragma once
/// \file
/// \brief A table model over the recorded trace events, optionally only the misses.
#include <QAbstractTableModel>

#include "view/session_state.h"

namespace rcgui {

/// Rows are recorded events (every one, or only misses and deferrals). Reads the
/// recorder lazily, so a million events cost nothing until they are scrolled to.
class EventLogModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;
    /// Follows `state` (null: shows nothing, e.g. while a worker owns the state).
    void setState(const rc::SessionState* state);
    void setMissesOnly(bool on);
    bool missesOnly() const { return missesOnly_; }
    /// The recorder index of a row's event.
    int eventAt(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    const rc::SessionState* state_ = nullptr;
    bool missesOnly_ = false;
    int rows_ = 0;
};

}  // namespace rcgui
