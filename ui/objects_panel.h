#pragma once
/// \file
/// \brief Dock panel: the scene's objects; selecting one highlights it in the view.
#include <QAbstractListModel>
#include <QListView>

#include "scene/scene.h"

namespace rcgui {

/// One row per object of a scene, its text made when the row is shown (a scene of tens
/// of thousands of polygons costs nothing until it is scrolled through).
class ObjectsModel : public QAbstractListModel {
    Q_OBJECT
public:
    using QAbstractListModel::QAbstractListModel;
    void setScene(const rc::Scene* scene);
    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;

private:
    const rc::Scene* scene_ = nullptr;
};

/// Lists the objects of a scene (id, shape, centre and radius of its bounding sphere,
/// material); the current row is the highlighted object.
class ObjectsPanel : public QListView {
    Q_OBJECT
public:
    explicit ObjectsPanel(QWidget* parent = nullptr);
    void setScene(const rc::Scene* scene);

signals:
    /// The object to highlight, -1 for none.
    void objectChosen(int object);

private:
    ObjectsModel* model_;
};

}  // namespace rcgui
