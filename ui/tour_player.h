#pragma once
/// \file
/// \brief The tour player: a lecture's stops, the strip that moves between them, the
/// caption above the picture, and the next stop's render made ahead while this one is shown.
#include <array>
#include <memory>
#include <vector>

#include <QObject>

#include "gui_options.h"
#include "session_controller.h"
#include "view/tour.h"

class QComboBox;
class QLabel;
class QToolBar;

namespace rcgui {

class MainWindow;

/// Plays a tour in a window. While a stop is shown and nothing else runs, the next stop's
/// render (and its compared render) is made on workers; reaching that stop takes them as
/// they are, finished or not, instead of starting new ones. The core is deterministic, so
/// a render made ahead is the render the stop would have made.
class TourPlayer : public QObject {
    Q_OBJECT
public:
    /// Adds the tour strip to `window`'s toolbars and `caption` holds the stop's caption.
    TourPlayer(MainWindow& window, QLabel* caption);
    ~TourPlayer() override;

    /// See MainWindow::setTour.
    void setTour(const rc::Tour& tour, std::vector<GuiOptions> stops);
    /// See MainWindow::goToStop.
    bool goToStop(int stop, bool wait);
    int stop() const { return stop_; }
    int stopCount() const { return int(stops_.size()); }
    QString caption() const;
    /// Renders made ahead (off: a stop renders when it is reached, as without a tour).
    void setAhead(bool on);

    /// The scene a render made ahead for scene spec `spec` uses (null: none is made).
    std::shared_ptr<const rc::Scene> aheadScene(const QString& spec) const;
    /// The render made ahead for exactly `config` (its worker stopped where it was), or null.
    std::unique_ptr<rc::SessionState> takeAhead(const rc::SessionConfig& config);
    /// The stop whose renders are being made or are made ahead (0: none).
    int aheadStop() const { return aheadStop_; }
    /// Whether a render is being made ahead now.
    bool aheadBusy() const;
    /// Renders made ahead that a stop took.
    int aheadTaken() const { return taken_; }
    /// Milliseconds from the last goToStop() to its picture complete: shown, and no render
    /// of the window running (-1 while it is not). Also written to the frame log as
    /// `stop-K-picture MILLISECONDS`.
    double lastPictureMs() const { return pictureMs_; }

signals:
    /// Every render made ahead for aheadStop() is finished.
    void aheadReady(int stop);

private:
    /// The window is idle or has shown a stop: the picture's time, then the next stop's renders.
    void onIdle();
    /// Starts making the next stop's renders when the window shows a stop and is idle.
    void maybeMakeAhead();
    /// Drops the renders made ahead.
    void dropAhead();
    QToolBar* buildBar();

    MainWindow& w_;
    QLabel* caption_;
    QToolBar* bar_ = nullptr;
    QComboBox* stopBox_ = nullptr;
    rc::Tour tour_;
    std::vector<GuiOptions> stops_;
    int stop_ = 0;
    bool aheadOn_ = true;
    /// The next stop's render and its compared render, with what each was made from
    struct Ahead {
        SessionController controller;
        rc::SessionConfig config;
        bool made = false;  ///< started for aheadStop_
    };
    std::array<Ahead, 2> ahead_;
    int aheadStop_ = 0;
    int taken_ = 0;
    double pictureStart_ = -1.0;  ///< FrameLog::now() at goToStop(), until its picture is complete
    double pictureMs_ = -1.0;
    bool shown_ = false;  ///< the window has shown the stop asked for last
};

/// Whether `a` and `b` make the same render: the same scene object and every option alike.
bool sameRender(const rc::SessionConfig& a, const rc::SessionConfig& b);

}  // namespace rcgui
