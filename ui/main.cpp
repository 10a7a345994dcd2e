/// \file
/// \brief raycache-gui: the interactive window, or a headless screenshot.
#include <cstdio>

#include <QApplication>
#include <QMessageBox>
#include <QTextStream>
#include <QTimer>

#include "frame_log.h"
#include "gui_options.h"
#include "main_window.h"
#include "screenshot.h"
#include "tour_player.h"

namespace {

/// Reads the tour `opt` names, every stop before anything is shown, so that a bad one is
/// found at once. False (and said on `err`) on an error.
bool readTour(const rcgui::GuiOptions& opt, rc::Tour& tour, std::vector<rcgui::GuiOptions>& stops, QTextStream& err) {
    QString message;
    try {
        tour = rc::loadTour(opt.tour.toStdString());
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            const auto o = rcgui::stopOptions(tour, k, opt, message);
            if (!o) {
                err << "raycache-gui: " << message << Qt::endl;
                return false;
            }
            stops.push_back(*o);
        }
        // What the flags cannot say: each stop's scene opens, its pixel, path and claims hold
        rc::checkTour(tour);
    } catch (const rc::TourError& e) {
        err << "raycache-gui: " << e.what() << Qt::endl;
        return false;
    }
    if (opt.stop > int(stops.size())) {
        err << "raycache-gui: --stop " << opt.stop << ": " << opt.tour << " has " << stops.size() << " stops" << Qt::endl;
        return false;
    }
    return true;
}

/// No display: render headless, to a PNG (the file named when none is given)
void chooseHeadless(rcgui::GuiOptions& opt, QTextStream& out) {
    const bool noDisplay = qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
    if (noDisplay && platform.isEmpty()) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        out << "raycache-gui: no display found: rendering headless (QT_QPA_PLATFORM=offscreen)" << Qt::endl;
    }
    const bool offscreen = qEnvironmentVariable("QT_QPA_PLATFORM") == "offscreen" ||
                           qEnvironmentVariable("QT_QPA_PLATFORM") == "minimal";
    if (opt.screenshot.isEmpty() && opt.record.isEmpty() && noDisplay && offscreen) {
        opt.screenshot = "raycache-gui.png";
        out << "raycache-gui: no --screenshot given: writing " << opt.screenshot << Qt::endl;
    }
}

/// --walk: each stop in turn once it is shown and nothing runs (not even a render made
/// ahead), then quit
void walk(rcgui::MainWindow& w) {
    constexpr int kIdleCheckMs = 100;
    auto* idle = new QTimer(&w);
    idle->setInterval(kIdleCheckMs);
    QObject::connect(&w, &rcgui::MainWindow::shown, idle, qOverload<>(&QTimer::start));
    QObject::connect(idle, &QTimer::timeout, &w, [&w, idle] {
        if (w.controller().busy() || w.compareController().busy() || w.tourPlayer().aheadBusy()) return;
        idle->stop();
        if (w.stop() > 0 && w.stop() < w.stopCount()) w.goToStop(w.stop() + 1);
        else QApplication::quit();
    });
}

/// The window first, then its rays, traced on the worker: it never waits for them
int runWindow(QApplication& app, const rcgui::GuiOptions& opt, const rc::Tour& tour,
              const std::vector<rcgui::GuiOptions>& stops, QTextStream& err) {
    rcgui::MainWindow w;
    w.setWorkerSessions(true);
    if (opt.largeFonts) w.setLargeFonts(true);
    if (opt.present) w.setPresentation(true);
    bool ok = true;
    w.setErrorReporter([&](const QString& title, const QString& text) {
        err << "raycache-gui: " << title.toLower() << ": " << text << Qt::endl;
        ok = false;
    });
    w.show();
    if (opt.walk) walk(w);
    if (!stops.empty()) {
        w.tourPlayer().setAhead(opt.renderAhead);
        w.setTour(tour, stops);
        w.goToStop(opt.stop);
    } else {
        w.apply(opt, false);
    }
    if (!ok) return 2;
    // From now on, errors are the user's to read in a message box
    w.setErrorReporter([&w](const QString& title, const QString& text) { QMessageBox::critical(&w, title, text); });
    return app.exec();
}

}  // namespace

int main(int argc, char** argv) {
    rcgui::FrameLog::sinceStart();  // the clock of first-frame starts here
    // Parse the command line: help exits 0, a bad option 2
    QStringList args;
    for (int i = 0; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    QTextStream out(stdout), err(stderr);
    rcgui::GuiOptions opt;
    QString message;
    switch (rcgui::parseGuiOptions(args, opt, message)) {
        case rcgui::ParseResult::Help: out << message << Qt::endl; return 0;
        case rcgui::ParseResult::Error:
            // One line: what is wrong, and where to read what is right
            err << "raycache-gui: " << message.simplified() << " (try raycache-gui --help)" << Qt::endl;
            return 2;
        case rcgui::ParseResult::Ok: break;
    }
    rc::Tour tour;
    std::vector<rcgui::GuiOptions> stops;
    if (!opt.tour.isEmpty() && !readTour(opt, tour, stops, err)) return 2;
    chooseHeadless(opt, out);
    rcgui::TimedApplication app(argc, argv);
    QApplication::setApplicationName("raycache-gui");
    if (!opt.frameLog.isEmpty() && !rcgui::FrameLog::instance().open(opt.frameLog)) {
        err << "raycache-gui: cannot write " << opt.frameLog << Qt::endl;
        return 2;
    }
    if (!opt.record.isEmpty()) return rcgui::recordSequence(opt, out, err);
    if (!opt.screenshot.isEmpty()) {
        if (tour.stops.empty()) return rcgui::renderScreenshot(opt, out, err);
        rcgui::GuiOptions shot = stops[std::size_t(opt.stop - 1)];
        shot.screenshot = opt.screenshot;
        return rcgui::renderScreenshot(shot, out, err, &tour, stops);
    }
    return runWindow(app, opt, tour, stops, err);
}
