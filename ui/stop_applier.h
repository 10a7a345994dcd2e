#pragma once
/// \file
/// \brief Applies a whole state to a window, as the command line or a tour stop gives it,
/// in its parts: the choices, the rays (on the worker in a live window), then the rest.
#include <optional>

#include <QObject>

#include "gui_options.h"

namespace rcgui {

class MainWindow;

/// MainWindow::apply() and the rest of it that waits for the rays.
class StopApplier : public QObject {
    Q_OBJECT
public:
    explicit StopApplier(MainWindow& window);

    /// See MainWindow::apply.
    bool apply(const GuiOptions& o, bool wait);
    /// The worker has traced what was asked: on to the stop's miss or deferral, or the rest.
    /// `completed` is false when it was cancelled (the rest is dropped).
    void onRunFinished(bool completed);

private:
    /// `o`'s choices: overlays, cache, order, search, size, compare, miss filter, panels.
    void choose(const GuiOptions& o);
    /// The next part of pending_: its run to a miss or deferral, else finish().
    void continuePending();
    /// The rest of apply(), once its rays are traced.
    bool finish(const GuiOptions& o, bool wait);
    /// Zoom and focus rectangle of `o` on the views (fitted when it gives neither).
    void frameViews(const GuiOptions& o);

    MainWindow& w_;
    std::optional<GuiOptions> pending_;  ///< apply()'s rest, waiting for its rays
    bool pendingRun_ = false;            ///< its run to the next miss or deferral has started
};

}  // namespace rcgui
