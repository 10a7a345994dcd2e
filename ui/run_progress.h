#pragma once
/// \file
/// \brief The status bar of a run on the worker: its progress, a Cancel button and its news.
#include <QObject>

class QMainWindow;
class QProgressBar;
class QPushButton;

namespace rcgui {

/// While the worker runs: how far it is, and the way to stop it.
class RunProgress : public QObject {
    Q_OBJECT
public:
    /// Adds the bar and the button to `window`'s status bar, hidden.
    explicit RunProgress(QMainWindow& window);
    /// Shown while busy, from 0.
    void setBusy(bool busy);
    /// The worker's news: `steps` traced, `progress` (0-1) of the eye rays.
    void show(qint64 steps, double progress);
    /// A run ended: finished, or cancelled.
    void ended(bool completed);

signals:
    void cancelClicked();

private:
    QMainWindow& window_;
    QProgressBar* bar_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

}  // namespace rcgui
