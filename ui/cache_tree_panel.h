#pragma once
/// \file
/// \brief Dock panel: the cache tree, one entry per ray-tree path.
#include <QTreeWidget>

#include "view/session_state.h"

namespace rcgui {

/// The cache tree's entries: path, state, origin, cached object, and the blocker list
/// length, cylinder radius or empty-cone angle the entry holds.
class CacheTreePanel : public QTreeWidget {
    Q_OBJECT
public:
    explicit CacheTreePanel(QWidget* parent = nullptr);
    /// Rebuilds from `state` (null: a worker is running; the panel is left as is); the
    /// entry of path `focusNode` (the ray in focus) is bold, flushed entries coloured.
    void refresh(const rc::SessionState* state, int focusNode = -1);
};

}  // namespace rcgui
