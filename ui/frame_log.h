#pragma once
/// \file
/// \brief The frame log: how long each task of the UI thread took, so that anyone can
/// check that the window never freezes (`raycache-gui --frame-log FILE`).
#include <QApplication>
#include <QFile>
#include <QString>

namespace rcgui {

/// Writes one line per UI-thread task, `NAME MILLISECONDS`: each event the application
/// delivers on the UI thread (outermost only: an event handled inside another is part of
/// it), named `EventType:ReceiverClass`, and the named phases of start-up, among them
/// `first-frame` (from start to the first painted window). Inside a task, each widget's
/// paint gets a line of its own, `paint:WidgetClass`, to tell which view a slow repaint owes.
class FrameLog {
public:
    /// The process's log (closed until open() is called).
    static FrameLog& instance();
    /// Starts logging to `file`; false when it cannot be written.
    bool open(const QString& file);
    bool enabled() const { return file_.isOpen(); }
    /// Adds a line; names have no spaces.
    void record(const QString& name, double milliseconds);
    /// Lines written so far.
    int lines() const { return lines_; }
    /// Milliseconds since the process started (since the first call of this function,
    /// which main() makes first thing), on the log's clock.
    static double sinceStart();
    /// The log's clock, in milliseconds: wall time by default (what a user waits), or,
    /// with the environment variable RAYCACHE_FRAME_CLOCK=cpu, the CPU time of the
    /// calling thread, which other processes on a busy machine do not inflate.
    static double now();

private:
    QFile file_;
    int lines_ = 0;
};

/// A QApplication whose notify() times every outermost event of the UI thread into the
/// frame log, and writes `first-frame` when the first window has painted.
class TimedApplication : public QApplication {
public:
    TimedApplication(int& argc, char** argv) : QApplication(argc, argv) {}
    bool notify(QObject* receiver, QEvent* event) override;

private:
    int depth_ = 0;
    bool paintSeen_ = false;   ///< a widget has painted
    bool firstFrame_ = false;  ///< first-frame is written
};

/// Times a named task of the UI thread into the frame log for as long as it lives.
class FrameTask {
public:
    explicit FrameTask(QString name) : name_(std::move(name)), start_(FrameLog::now()) {}
    ~FrameTask() { FrameLog::instance().record(name_, FrameLog::now() - start_); }
    FrameTask(const FrameTask&) = delete;
    FrameTask& operator=(const FrameTask&) = delete;

private:
    QString name_;
    double start_;
};

}  // namespace rcgui
