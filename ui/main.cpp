/// \file
/// \brief raycache-gui: the interactive window, or a headless screenshot.
#include <cstdio>

#include <QApplication>
#include <QMessageBox>
#include <QTextStream>

#include "gui_options.h"
#include "main_window.h"
#include "screenshot.h"

int main(int argc, char** argv) {
    QStringList args;
    for (int i = 0; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    QTextStream out(stdout), err(stderr);
    rcgui::GuiOptions opt;
    QString message;
    switch (rcgui::parseGuiOptions(args, opt, message)) {
        case rcgui::ParseResult::Help: out << message << Qt::endl; return 0;
        case rcgui::ParseResult::Error:
            err << "raycache-gui: " << message << "\n(try raycache-gui --help)" << Qt::endl;
            return 2;
        case rcgui::ParseResult::Ok: break;
    }
    // No display: render headless, to a PNG
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
    QApplication app(argc, argv);
    QApplication::setApplicationName("raycache-gui");
    if (!opt.record.isEmpty()) return rcgui::recordSequence(opt, out, err);
    if (!opt.screenshot.isEmpty()) return rcgui::renderScreenshot(opt, out, err);

    rcgui::MainWindow w;
    if (!rcgui::applyOptions(w, opt, err)) return 2;
    // From now on, errors are the user's to read in a message box
    w.setErrorReporter([&w](const QString& title, const QString& text) {
        QMessageBox::critical(&w, title, text);
    });
    w.show();
    return app.exec();
}
