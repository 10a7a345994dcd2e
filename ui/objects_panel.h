#pragma once
/// \file
/// \brief Dock panel: the scene's objects; selecting one highlights it in the view.
#include <QListWidget>

#include "scene/scene.h"

namespace rcgui {

/// Lists the objects of a scene (id, shape, centre and radius of its bounding sphere,
/// material); the current row is the highlighted object.
class ObjectsPanel : public QListWidget {
    Q_OBJECT
public:
    explicit ObjectsPanel(QWidget* parent = nullptr);
    void setScene(const rc::Scene* scene);

signals:
    /// The object to highlight, -1 for none.
    void objectChosen(int object);
};

}  // namespace rcgui
