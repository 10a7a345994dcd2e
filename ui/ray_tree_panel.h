#pragma once
/// \file
/// \brief Dock panel: the ray tree of one pixel, from the recorded events.
#include <QTreeWidget>

#include "view/session_state.h"

namespace rcgui {

/// Every ray of a pixel as a tree (children under the ray that spawned them), with its
/// path, kind, hit object, cache decision and tests; deferred attempts are listed too.
class RayTreePanel : public QTreeWidget {
    Q_OBJECT
public:
    explicit RayTreePanel(QWidget* parent = nullptr);
    /// Shows the rays of `pixel` (-1: clear). `state` may be null (a worker is running).
    void showPixel(const rc::SessionState* state, int pixel);
    int pixel() const { return pixel_; }
    /// Marks the row of recorded event `event` as current (no rayChosen signal).
    void setCurrentEvent(int event);

signals:
    /// A ray was chosen: the index of its event in the recorder.
    void rayChosen(int event);

private:
    int pixel_ = -1;
};

}  // namespace rcgui
