#pragma once
/// \file
/// \brief What the window has in focus: a pixel, one of its rays, an object; chosen by a
/// click, a panel, a cache-tree path, or as the ray worth showing.
#include <QObject>
#include <QString>

namespace rcgui {

class MainWindow;

/// Chooses the window's selection (MainWindow::selection()) and shows it everywhere.
class RaySelector : public QObject {
    Q_OBJECT
public:
    explicit RaySelector(MainWindow& window);
    /// See MainWindow::selectPixel, selectEvent, selectObject, selectRay, focusShowcase.
    void selectPixel(int x, int y);
    bool selectEvent(int event);
    void selectObject(int object);
    bool selectRay(int x, int y, const QString& path, QString& error);
    int focusShowcase();

private:
    MainWindow& w_;
};

}  // namespace rcgui
