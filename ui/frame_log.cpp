#include "frame_log.h"

#include <ctime>

#include <QElapsedTimer>
#include <QEvent>
#include <QMetaEnum>
#include <QThread>
#include <QWidget>

namespace rcgui {

FrameLog& FrameLog::instance() {
    static FrameLog log;
    return log;
}

bool FrameLog::open(const QString& file) {
    file_.setFileName(file);
    return file_.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text);
}

void FrameLog::record(const QString& name, double milliseconds) {
    if (!file_.isOpen()) return;
    file_.write(QString("%1 %2\n").arg(name).arg(milliseconds, 0, 'f', 3).toUtf8());
    file_.flush();
    ++lines_;
}

double FrameLog::now() {
    static const bool cpu = qEnvironmentVariable("RAYCACHE_FRAME_CLOCK") == "cpu";
    if (cpu) {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
    }
    static QElapsedTimer wall = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    return double(wall.nsecsElapsed()) * 1e-6;
}

double FrameLog::sinceStart() {
    static const double start = now();
    return now() - start;
}

bool TimedApplication::notify(QObject* receiver, QEvent* event) {
    FrameLog& log = FrameLog::instance();
    if (!log.enabled() || QThread::currentThread() != thread()) return QApplication::notify(receiver, event);
    if (event->type() == QEvent::Paint && receiver && receiver->isWidgetType()) paintSeen_ = true;
    if (depth_ > 0) {
        // Inside a task: a widget's paint is logged too (lower case), to tell which view costs
        if (event->type() != QEvent::Paint || !receiver) return QApplication::notify(receiver, event);
        const QString name = QString("paint:") + receiver->metaObject()->className();
        const double start = FrameLog::now();
        const bool handled = QApplication::notify(receiver, event);
        log.record(name, FrameLog::now() - start);
        return handled;
    }
    // An outermost event of the UI thread: one task (the events it sends are part of it)
    // Named before it is delivered: a DeferredDelete deletes its receiver (and the event)
    const char* type = QMetaEnum::fromType<QEvent::Type>().valueToKey(event->type());
    const int typeNumber = int(event->type());
    const char* cls = receiver ? receiver->metaObject()->className() : "none";
    const double start = FrameLog::now();
    ++depth_;
    const bool handled = QApplication::notify(receiver, event);
    --depth_;
    const double ms = FrameLog::now() - start;
    log.record(QString("%1:%2").arg(type ? QString(type) : QString::number(typeNumber), QString(cls)), ms);
    // The first window painted: how long the user waited for it
    if (!firstFrame_ && paintSeen_) {
        firstFrame_ = true;
        log.record("first-frame", FrameLog::sinceStart());
    }
    return handled;
}

}  // namespace rcgui
