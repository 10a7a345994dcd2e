#include "screenshot.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QPixmap>

#include "image_view.h"
#include "view/session_state.h"
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
    const bool applied = w.apply(o, true) && ok;
    // `ok` dies with this call: later errors only go to the stream
    w.setErrorReporter([&err](const QString& title, const QString& message) {
        err << "raycache-gui: " << title.toLower() << ": " << message << Qt::endl;
    });
    return applied;
}

int renderScreenshot(const GuiOptions& o, QTextStream& out, QTextStream& err, const rc::Tour* tour,
                     const std::vector<GuiOptions>& stops) {
    MainWindow w;
    GuiOptions opts = o;
    if (opts.steps < 0) opts.steps = 20000;
    // The window at its size first: the zoom and focus rectangle fit what it shows
    w.resize(opts.window);
    w.show();
    QApplication::processEvents();
    if (tour) {
        if (opts.largeFonts) w.setLargeFonts(true);
        if (opts.present) w.setPresentation(true);
        w.setTour(*tour, stops);
        bool ok = true;
        w.setErrorReporter([&](const QString& title, const QString& message) {
            err << "raycache-gui: " << title.toLower() << ": " << message << Qt::endl;
            ok = false;
        });
        if (!w.goToStop(opts.stop, true) || !ok) return 2;
    } else if (!applyOptions(w, opts, err)) {
        return 2;
    }
    w.resize(opts.window);
    // A first paint places the caption and key, and the view makes room for them
    QApplication::processEvents();
    w.grab();
    QApplication::processEvents();
    const QPixmap shot = w.grab();
    if (shot.isNull() || !shot.save(opts.screenshot, "PNG")) {
        err << "raycache-gui: cannot write " << opts.screenshot << Qt::endl;
        return 1;
    }
    const rc::SessionState* s = w.controller().state();
    const QString scene = tour ? stops[std::size_t(opts.stop - 1)].scene : opts.scene;
    out << "raycache-gui: wrote " << QFileInfo(opts.screenshot).absoluteFilePath() << " ("
        << (tour ? QString("stop %1 of %2, ").arg(opts.stop).arg(stops.size()) : QString()) << scene << ", "
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
        rc::SessionState* s = w.controller().state();
        if (!s) break;
        const bool more = s->runUntil(rc::RunGoal::ToStep, s->session().steps() + o.every) && !s->session().done();
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
    const rc::SessionState* s = w.controller().state();
    out << "raycache-gui: wrote " << frame << " frames to " << QFileInfo(o.record).absoluteFilePath() << " ("
        << opts.scene << ", every " << o.every << " steps, " << (s ? s->session().steps() : 0) << " steps)" << Qt::endl;
    return 0;
}

}  // namespace rcgui
