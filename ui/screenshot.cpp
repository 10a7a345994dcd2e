#include "screenshot.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QPixmap>

#include "image_view.h"
#include "session_state.h"
#include "main_window.h"
#include "scene_view.h"

namespace rcgui {

bool applyOptions(MainWindow& w, const GuiOptions& o, QTextStream& err) {
    bool ok = true;
    w.setErrorReporter([&](const QString& title, const QString& message) {
        err << "raycache-gui: " << title.toLower() << ": " << message << Qt::endl;
        ok = false;
    });
    if (o.largeFonts) w.setLargeFonts(true);
    if (o.present) w.setPresentation(true);
    w.setOverlays(o.overlays);
    // Choose everything first, then load: one session is built, with these choices
    w.setCache(o.cache);
    w.setOrder(o.order);
    w.setAccel(o.accel);
    w.setSampling(o.sampling);
    if (o.width > 0 || o.height > 0) w.setImageSize(o.width, o.height);
    if (!w.loadScene(o.scene) || !ok) {
        w.setErrorReporter([&err](const QString&, const QString& message) { err << message << Qt::endl; });
        return false;
    }
    if (o.steps > 0) {
        if (SessionState* s = w.controller().state()) s->runUntil(RunGoal::ToStep, o.steps);
    }
    if (o.compare) {
        QString why;
        if (!w.setCompare(toString(*o.compare), why)) {
            err << "raycache-gui: --compare: " << why << Qt::endl;
            return false;
        }
        w.syncCompare(true);
    }
    w.setHeatmap(o.heatmap);
    if (o.sceneView) {
        w.setSceneView(true);
        w.sceneView()->setAngle(o.sceneAngle);
        w.sceneView()->setOrbit(o.orbitYaw, o.orbitPitch);
    }
    w.refresh();
    // The scene view with nothing selected: a ray worth seeing from the side
    if (o.firstImpression || (o.sceneView && o.select.x() < 0)) w.focusShowcase();
    if (o.select.x() >= 0) {
        QString why;
        if (!w.selectRay(o.select.x(), o.select.y(), o.selectPath, why)) {
            err << "raycache-gui: --select: " << why << Qt::endl;
            w.setErrorReporter([&err](const QString&, const QString& message) { err << message << Qt::endl; });
            return false;
        }
    }
    // `ok` dies with this call: later errors only go to the stream
    w.setErrorReporter([&err](const QString& title, const QString& message) {
        err << "raycache-gui: " << title.toLower() << ": " << message << Qt::endl;
    });
    return true;
}

int renderScreenshot(const GuiOptions& o, QTextStream& out, QTextStream& err) {
    MainWindow w;
    GuiOptions opts = o;
    if (opts.steps < 0) opts.steps = 20000;
    if (!applyOptions(w, opts, err)) return 2;
    w.resize(opts.window);
    w.show();
    QApplication::processEvents();
    ImageView* view = w.imageView();
    view->fit();
    if (opts.compare) w.compareView()->fit();
    if (opts.zoom != 1.0) {
        // Zoom about the selected pixel, else the pixel of the ray being traced
        QPointF centre(view->image().width() / 2.0, view->image().height() / 2.0);
        const SessionState* s = w.controller().state();
        int pixel = w.selection().pixel;
        if (pixel < 0 && s && s->recorder().lastEvent()) pixel = s->recorder().lastEvent()->task.pixel;
        if (s && pixel >= 0) centre = QPointF(pixel % s->width() + 0.5, pixel / s->width() + 0.5);
        const double z = view->zoom() * opts.zoom;
        view->setZoom(z, QPointF(view->width() / 2.0, view->height() / 2.0) - z * centre);
    }
    QApplication::processEvents();
    const QPixmap shot = w.grab();
    if (shot.isNull() || !shot.save(opts.screenshot, "PNG")) {
        err << "raycache-gui: cannot write " << opts.screenshot << Qt::endl;
        return 1;
    }
    const SessionState* s = w.controller().state();
    out << "raycache-gui: wrote " << QFileInfo(opts.screenshot).absoluteFilePath() << " (" << opts.scene << ", "
        << (s ? s->session().steps() : 0) << " steps, " << shot.width() << "x" << shot.height() << ")" << Qt::endl;
    return 0;
}

}  // namespace rcgui

namespace rcgui {

int recordSequence(const GuiOptions& o, QTextStream& out, QTextStream& err) {
    const QDir dir(o.record);
    if (!QDir().mkpath(o.record)) {
        err << "raycache-gui: cannot create " << o.record << Qt::endl;
        return 1;
    }
    MainWindow w;
    GuiOptions opts = o;
    opts.steps = 0;
    if (!applyOptions(w, opts, err)) return 2;
    w.resize(opts.window);
    w.show();
    QApplication::processEvents();
    w.imageView()->fit();
    int frame = 0;
    for (;;) {
        SessionState* s = w.controller().state();
        if (!s) break;
        const bool more = s->runUntil(RunGoal::ToStep, s->session().steps() + o.every) && !s->session().done();
        w.refresh();
        QApplication::processEvents();
        const QString file = dir.filePath(QString("frame_%1.png").arg(frame, 5, 10, QChar('0')));
        if (!w.grab().save(file, "PNG")) {
            err << "raycache-gui: cannot write " << file << Qt::endl;
            return 1;
        }
        ++frame;
        if (!more || frame >= kMaxRecordedFrames) break;
    }
    const SessionState* s = w.controller().state();
    out << "raycache-gui: wrote " << frame << " frames to " << QFileInfo(o.record).absoluteFilePath() << " ("
        << opts.scene << ", every " << o.every << " steps, " << (s ? s->session().steps() : 0) << " steps)" << Qt::endl;
    return 0;
}

}  // namespace rcgui
