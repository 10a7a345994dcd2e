#include "objects_panel.h"

namespace rcgui {

ObjectsPanel::ObjectsPanel(QWidget* parent) : QListWidget(parent) {
    setUniformItemSizes(true);
    connect(this, &QListWidget::currentRowChanged, this, [this](int row) { emit objectChosen(row); });
}

void ObjectsPanel::setScene(const rc::Scene* scene) {
    const QSignalBlocker block(this);
    clear();
    if (!scene) return;
    for (int i = 0; i < scene->size(); ++i) {
        const rc::Object& o = scene->objects[i];
        const rc::Material& m = scene->materials[o.material];
        addItem(QString("#%1 %2  c=(%3, %4, %5) r=%6  ks=%7 kt=%8")
                    .arg(i)
                    .arg(o.shape == rc::Shape::Sphere ? "sphere " : "polygon")
                    .arg(o.bound.c.x, 0, 'g', 4).arg(o.bound.c.y, 0, 'g', 4).arg(o.bound.c.z, 0, 'g', 4)
                    .arg(o.bound.r, 0, 'g', 4).arg(m.ks, 0, 'g', 3).arg(m.kt, 0, 'g', 3));
    }
}

}  // namespace rcgui
