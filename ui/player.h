#pragma once
/// \file
/// \brief Play: the window's render traced a few rays at a time, at the speed the step
/// toolbar chooses, on the UI thread.
#include <QObject>
#include <QTimer>

namespace rcgui {

class MainWindow;

/// Traces rays at a steady rate while on, and stops at the end of the render.
class Player : public QObject {
    Q_OBJECT
public:
    explicit Player(MainWindow& window);
    void setPlaying(bool on);
    bool playing() const { return timer_.isActive(); }

private:
    void onTick();
    MainWindow& w_;
    QTimer timer_;
    double credit_ = 0.0;  ///< rays owed, the fraction a tick left over
};

}  // namespace rcgui
