#include "panels.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QTimer>

#include "cache_tree_panel.h"
#include "event_log_panel.h"
#include "frame_log.h"
#include "gui_options.h"
#include "objects_panel.h"
#include "ray_tree_panel.h"
#include "stats_panel.h"
#include "view/ray_focus.h"

namespace rcgui {

namespace {
// The docks' first sizes: the right-hand column wide enough for the ray tree's path
// column, the bottom row tall enough for about eight lines of the event log
constexpr int kRightColumnWidth = 520;
constexpr int kBottomRowHeight = 180;
}  // namespace

Panels::Panels(QMainWindow& window) : QObject(&window), window_(window) {
    rayTree_ = new RayTreePanel(&window);
    cacheTree_ = new CacheTreePanel(&window);
    stats_ = new StatsPanel(&window);
    eventLog_ = new EventLogPanel(&window);
    objects_ = new ObjectsPanel(&window);
    // The right-hand panels run the window's full height and the event log sits under the
    // image only: stacked under both, they made the window taller than a 1280x720
    // projector with large fonts (818 pixels)
    window.setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    QDockWidget* rt = dock("Ray tree", rayTree_, Qt::RightDockWidgetArea);
    QDockWidget* ct = dock("Cache tree", cacheTree_, Qt::RightDockWidgetArea);
    QDockWidget* st = dock("Statistics", stats_, Qt::RightDockWidgetArea);
    QDockWidget* log = dock("Event log", eventLog_, Qt::BottomDockWidgetArea);
    QDockWidget* obj = dock("Objects", objects_, Qt::BottomDockWidgetArea);
    docks_ = {rt, ct, st, log, obj};  // in panelNames()' order
    for (QDockWidget* d : docks_)
        connect(d, &QDockWidget::visibilityChanged, this, [this](bool shown) {
            if (shown) QTimer::singleShot(0, this, &Panels::refreshDue);
        });
    window.tabifyDockWidget(rt, ct);
    rt->raise();
    window.tabifyDockWidget(log, obj);
    log->raise();
    window.resizeDocks({rt}, {kRightColumnWidth}, Qt::Horizontal);
    window.resizeDocks({log}, {kBottomRowHeight}, Qt::Vertical);
}

QDockWidget* Panels::dock(const QString& title, QWidget* w, Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, &window_);
    d->setObjectName(title);
    d->setWidget(w);
    window_.addDockWidget(area, d);
    return d;
}

QList<QDockWidget*> Panels::docksNamed(const QStringList& names) const {
    QList<QDockWidget*> out;
    for (int i = 0; i < int(docks_.size()); ++i)
        if (names.contains(panelNames()[i])) out << docks_[std::size_t(i)];
    return out;
}

void Panels::show(const QStringList& names) {
    const QList<QDockWidget*> on = docksNamed(names);
    for (QDockWidget* d : docks_) {
        d->setVisible(on.contains(d));
        if (on.contains(d)) d->raise();
    }
}

void Panels::refresh(const rc::SessionState& s, const rc::SessionState* compared, const rc::Selection& selection) {
    if (stats_->isVisibleTo(&window_)) {
        FrameTask task("refresh-statistics");
        stats_->refresh(&s, compared);
    }
    if (cacheTree_->isVisibleTo(&window_)) {
        FrameTask task("refresh-cache-tree");
        const auto focus = rc::RayFocus::of(s, selection);
        cacheTree_->refresh(&s, focus ? focus->node : -1);
    }
    if (eventLog_->isVisibleTo(&window_)) {
        FrameTask task("refresh-event-log");
        eventLog_->refresh(&s);
    }
    if (rayTree_->isVisibleTo(&window_)) {
        FrameTask task("refresh-ray-tree");
        // The ray tree follows the selected pixel, else the pixel being traced
        int pixel = selection.pixel;
        if (pixel < 0 && s.recorder().lastEvent()) pixel = s.recorder().lastEvent()->task.pixel;
        rayTree_->showPixel(&s, pixel);
        if (const auto f = rc::RayFocus::of(s, selection)) rayTree_->setCurrentEvent(f->event);
    }
}

void Panels::letGo() {
    eventLog_->refresh(nullptr);
    rayTree_->showPixel(nullptr, -1);
}

}  // namespace rcgui
