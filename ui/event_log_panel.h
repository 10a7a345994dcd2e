#pragma once
/// \file
/// \brief Dock panel: the event log, filterable to cache misses.
#include <QWidget>

#include "search/counters.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QTableView;

namespace rcgui {

class EventLogModel;
}
namespace rc { class SessionState; }
namespace rcgui {

/// A table of trace events with a "misses only" filter; activating a row selects its
/// pixel and ray.
class EventLogPanel : public QWidget {
    Q_OBJECT
public:
    explicit EventLogPanel(QWidget* parent = nullptr);
    void refresh(const rc::SessionState* state);
    EventLogModel* model() const { return model_; }
    void setMissesOnly(bool on);
    /// Shows only the misses of `r` (rc::MissReason::None: as Misses only says).
    void setReason(rc::MissReason r);

signals:
    /// A row was activated: the recorder index of its event.
    void eventChosen(int event);
    /// The reason box changed: Next miss stops at misses of this reason only.
    void reasonChosen(rc::MissReason r);

private:
    EventLogModel* model_;
    QTableView* table_;
    QCheckBox* missesOnly_;
    QLabel* shown_;  ///< how many of the events the table holds, when not all
    QCheckBox* follow_;
    QComboBox* reason_;
};

}  // namespace rcgui
