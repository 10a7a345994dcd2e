#include "ray_selector.h"

#include <QStatusBar>

#include "main_window.h"
#include "panels.h"
#include "ray_tree_panel.h"
#include "view/overlay_layers.h"

namespace rcgui {

RaySelector::RaySelector(MainWindow& window) : QObject(&window), w_(window) {}

int RaySelector::focusShowcase() {
    const rc::SessionState* s = w_.controller_.state();
    if (!s) return -1;
    // The paper's Figure 2 on screen, or the newest hit (rc::showcaseEvent)
    const int best = rc::showcaseEvent(*s);
    if (best >= 0) selectEvent(best);
    return best;
}

bool RaySelector::selectRay(int x, int y, const QString& path, QString& error) {
    const rc::SessionState* s = w_.controller_.state();
    if (!s) {
        error = "no render to select in";
        return false;
    }
    if (x < 0 || y < 0 || x >= s->width() || y >= s->height()) {
        error = QString("pixel (%1,%2) is outside the %3x%4 image").arg(x).arg(y).arg(s->width()).arg(s->height());
        return false;
    }
    selectPixel(x, y);
    if (path.isEmpty()) return true;
    std::string why;
    const int found = rc::eventAtPath(*s, y * s->width() + x, path.toStdString(), why);
    if (found < 0) {
        error = QString::fromStdString(why);
        return false;
    }
    return selectEvent(found);
}

void RaySelector::selectPixel(int x, int y) {
    const rc::SessionState* s = w_.controller_.state();
    if (!s || x < 0 || y < 0 || x >= s->width() || y >= s->height()) {
        w_.selection_.pixel = -1;
    } else {
        w_.selection_.pixel = y * s->width() + x;
        w_.statusBar()->showMessage(QString("pixel (%1, %2)").arg(x).arg(y));
    }
    w_.selection_.event = -1;
    w_.panels_->rayTree()->showPixel(s, w_.selection_.pixel);
    w_.viewsChanged();
}

bool RaySelector::selectEvent(int event) {
    const rc::SessionState* s = w_.controller_.state();
    if (!s || event < 0 || std::size_t(event) >= s->recorder().events().size()) return false;
    const int pixel = s->recorder().events()[std::size_t(event)].pixel;
    if (pixel != w_.selection_.pixel) selectPixel(pixel % s->width(), pixel / s->width());
    w_.selection_.event = event;
    w_.panels_->rayTree()->setCurrentEvent(event);
    w_.viewsChanged();
    return true;
}

void RaySelector::selectObject(int object) {
    w_.selection_.object = object;
    w_.viewsChanged();
}

}  // namespace rcgui
