#pragma once
/// \file
/// \brief The window's dock panels: ray tree, cache tree, statistics, event log and
/// objects, which of them are shown, and their refresh from a render.
#include <vector>

#include <QList>
#include <QObject>
#include <QStringList>

#include "view/ray_focus.h"
#include "view/session_state.h"

class QDockWidget;
class QMainWindow;

namespace rcgui {

class CacheTreePanel;
class EventLogPanel;
class ObjectsPanel;
class RayTreePanel;
class StatsPanel;

/// The docks of a window, in panelNames()' order.
class Panels : public QObject {
    Q_OBJECT
public:
    /// Makes the panels and docks them into `window` (the right-hand ones its full height).
    explicit Panels(QMainWindow& window);

    /// Shows the docks `names` lists (panelNames()), raised, and hides the others.
    void show(const QStringList& names);
    /// The docks `names` lists.
    QList<QDockWidget*> docksNamed(const QStringList& names) const;
    const std::vector<QDockWidget*>& docks() const { return docks_; }
    /// Refreshes the panels on screen from `s` (with `compared` beside it, if any), the
    /// ray in focus being `selection`'s; panels out of sight wait until they are shown.
    void refresh(const rc::SessionState& s, const rc::SessionState* compared, const rc::Selection& selection);
    /// The worker owns the state: every panel lets go of its views of it.
    void letGo();

    RayTreePanel* rayTree() const { return rayTree_; }
    CacheTreePanel* cacheTree() const { return cacheTree_; }
    StatsPanel* stats() const { return stats_; }
    EventLogPanel* eventLog() const { return eventLog_; }
    ObjectsPanel* objects() const { return objects_; }

signals:
    /// A dock came into sight: it wants the state.
    void refreshDue();

private:
    QDockWidget* dock(const QString& title, QWidget* w, Qt::DockWidgetArea area);
    QMainWindow& window_;
    std::vector<QDockWidget*> docks_;  ///< in panelNames()' order
    RayTreePanel* rayTree_ = nullptr;
    CacheTreePanel* cacheTree_ = nullptr;
    StatsPanel* stats_ = nullptr;
    EventLogPanel* eventLog_ = nullptr;
    ObjectsPanel* objects_ = nullptr;
};

}  // namespace rcgui
