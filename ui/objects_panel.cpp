#include "objects_panel.h"

#include <QItemSelectionModel>
#include <QSignalBlocker>

namespace rcgui {

void ObjectsModel::setScene(const rc::Scene* scene) {
    beginResetModel();
    scene_ = scene;
    endResetModel();
}

int ObjectsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !scene_ ? 0 : scene_->size();
}

QVariant ObjectsModel::data(const QModelIndex& index, int role) const {
    if (role != Qt::DisplayRole || !scene_ || index.row() < 0 || index.row() >= scene_->size()) return {};
    const int i = index.row();
    const rc::Object& o = scene_->objects[std::size_t(i)];
    const rc::Material& m = scene_->materials[o.material];
    return QString("#%1 %2  c=(%3, %4, %5) r=%6  ks=%7 kt=%8")
        .arg(i)
        .arg(o.shape == rc::Shape::Sphere ? "sphere " : "polygon")
        .arg(o.bound.c.x, 0, 'g', 4).arg(o.bound.c.y, 0, 'g', 4).arg(o.bound.c.z, 0, 'g', 4)
        .arg(o.bound.r, 0, 'g', 4).arg(m.ks, 0, 'g', 3).arg(m.kt, 0, 'g', 3);
}

ObjectsPanel::ObjectsPanel(QWidget* parent) : QListView(parent), model_(new ObjectsModel(this)) {
    setUniformItemSizes(true);
    setModel(model_);
    connect(selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) { emit objectChosen(current.isValid() ? current.row() : -1); });
}

void ObjectsPanel::setScene(const rc::Scene* scene) {
    const QSignalBlocker block(this);
    model_->setScene(scene);
}

}  // namespace rcgui
