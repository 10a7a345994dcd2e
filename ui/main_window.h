#pragma once
/// \file
/// \brief The main window: the image view, the stepping toolbar, overlay toggles and
/// the dock panels, around one SessionController.
#include <functional>
#include <memory>
#include <optional>

#include <QMainWindow>
#include <QTimer>

#include "gui_options.h"
#include "overlay_options.h"
#include "overlay_painter.h"
#include "session_controller.h"

class QAction;
class QCheckBox;
class QComboBox;
class QDockWidget;
class QLabel;
class QSlider;
class QProgressBar;
class QPushButton;
class QSplitter;
class QToolBar;

namespace rcgui {

/// The folder of NFF scenes the Scene menu lists: $RAYCACHE_SCENES, else the project's
/// scenes/ as configured at build time.
QString scenesFolder();

}
namespace rc { class SessionState; }
namespace rcgui {
/// The hover text of pixel (x, y) of a render (empty outside it or without one).
QString pixelTooltip(const rc::SessionState* s, int x, int y);

class CacheTreePanel;
class EventLogPanel;
class ImageView;
class ObjectsPanel;
class RayTreePanel;
class SceneView;
class StatsPanel;

/// The RayCache window. Every action is also a public slot, so tests and the
/// screenshot mode drive the window exactly as a user would.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Shows an error to the user. The default opens a modal QMessageBox; tests and the
    /// headless mode install their own.
    using ErrorReporter = std::function<void(const QString& title, const QString& message)>;

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    void setErrorReporter(ErrorReporter r) { reportError_ = std::move(r); }
    /// Builds each new render on the worker, so that the window never waits for a large
    /// scene's render to be made, and reads long event logs into the overlay layers over
    /// several paints (the interactive window; tests and screenshots build them here, and
    /// have their state and layers at once).
    void setWorkerSessions(bool on);
    /// Events of the log each layer reads in one paint of the interactive window.
    static constexpr std::size_t kLayerEventsPerPaint = 100000;

    /// Loads a built-in scene spec or an NFF file and starts a new render of it. On an
    /// error, reports it (file:line:column: message) and keeps the current scene.
    bool loadScene(const QString& spec);
    /// The scene being rendered (null before the first load).
    const rc::Scene* scene() const { return scene_.get(); }
    void setCache(rc::CacheKind k);
    /// The Scene menu's entries.
    QStringList sceneChoices() const;
    /// The Cache box's entries, and the one it shows.
    QStringList cacheChoices() const;
    QString cacheShown() const;
    /// Labels of the overlay boxes offered for the current cache and order.
    QStringList offeredOverlays() const;
    void setOrder(rc::OrderKind k);
    /// What answers complete searches (linear, grid, bvh).
    void setAccel(rc::AccelKind k);
    /// Distributed ray tracing's samples for the next session (no new session is made).
    void setSampling(const rc::Sampling& s) { options_.shading.sampling = s; }
    /// Selects pixel (x, y) and its ray at cache-tree path `path` (empty: its eye ray).
    /// On a bad pixel or path, says why in `error` and returns false.
    bool selectRay(int x, int y, const QString& path, QString& error);
    /// Image size; 0 x 0 means the scene's own.
    void setImageSize(int width, int height);
    void setOverlays(const Overlays& o);
    const Overlays& overlays() const { return overlays_; }
    void setHeatmap(Heatmap h);
    void setLargeFonts(bool on);
    /// Presentation mode: the panels and the render toolbar hidden, large fonts.
    void setPresentation(bool on);
    /// Runs a second render with another cache and order beside the first, in lockstep:
    /// the same step count, overlays, selection and heatmap scale. On a bad spec, says
    /// why in `error`, keeps everything as it was and returns false. "off" or "" ends it.
    bool setCompare(const QString& spec, QString& error);
    /// The compared render's controller (its state is null when there is none).
    SessionController& compareController() { return compare_; }
    const std::optional<CompareChoice>& compareChoice() const { return compareChoice_; }
    ImageView* compareView() const { return compareView_; }
    const OverlayPainter& compareOverlayPainter() const { return comparePainter_; }
    /// Brings the compared render to the first one's step count (on the calling thread
    /// when the gap is small or `now`, else on its worker).
    void syncCompare(bool now = false);
    /// Shows or hides the view of the 3D scene.
    void setSceneView(bool on);
    SceneView* sceneView() const { return sceneView_; }
    /// The statistics panel.
    StatsPanel* statsPanel() const { return stats_; }
    /// Selects a pixel to inspect (-1, -1 clears).
    void selectPixel(int x, int y);
    /// Puts a ray worth showing in focus: the newest eye ray that hit an object whose
    /// blocker hull holds potential blockers (else the newest hit). Returns its event, or -1.
    int focusShowcase();
    /// Puts recorded event `event` in focus (its pixel selected); false if there is no such event.
    bool selectEvent(int event);
    void selectObject(int object);
    const rc::Selection& selection() const { return selection_; }

    /// Applies a whole state, as the command line or a tour stop gives it: scene, cache,
    /// order, search, size, overlays, heatmap, compare, scene view and angle, the first
    /// `o.steps` rays, selection, zoom or focus rectangle, miss filter. What `o` leaves out
    /// is reset (no compare, no scene view, the image fitted). The rays are traced on the
    /// worker, and the rest applied when it is done, unless `wait`. False (and the error
    /// reported) on a bad scene or selection.
    bool apply(const GuiOptions& o, bool wait);
    /// Opens a tour whose stops' options are already read (stopOptions()); shows its strip.
    void setTour(const rc::Tour& tour, std::vector<GuiOptions> stops);
    /// Goes to stop `stop` (from 1) of the tour, as written. False if there is no such stop.
    bool goToStop(int stop, bool wait = false);
    /// The stop shown (from 1; 0: no tour) and how many there are.
    int stop() const { return stop_; }
    int stopCount() const { return int(stops_.size()); }
    /// The tour's caption as shown above the image ("" without a tour).
    QString tourCaption() const;
    /// Next miss stops only at misses of this reason (rc::MissReason::None: any).
    void setMissFilter(rc::MissReason r);
    /// Shows the docks `names` lists (panelNames()), raised, and hides the others.
    void showPanels(const QStringList& names);
    rc::MissReason missFilter() const { return missFilter_; }

    SessionController& controller() { return controller_; }
    const OverlayPainter& overlayPainter() const { return overlayPainter_; }
    ImageView* imageView() const { return view_; }
    RayTreePanel* rayTreePanel() const { return rayTree_; }
    EventLogPanel* eventLogPanel() const { return eventLog_; }

public slots:
    /// Rebuilds the render from the current scene and choices.
    void resetSession();
    void stepRay();
    void stepPixel();
    void runToNextMiss();
    void runToNextDeferral();
    /// Moves to step `step`, forwards by tracing, backwards from a checkpoint.
    void goToStep(qint64 step);
    void runToEnd();
    void stepBack();
    void cancelRun();
    void setPlaying(bool on);
    void nextStop() { goToStop(stop_ + 1); }
    void previousStop() { goToStop(stop_ - 1); }
    /// Back to the stop as written, after stepping, selecting or toggling from it.
    void restoreStop() { goToStop(stop_); }
    void openSceneDialog();
    /// Refreshes the picture and every panel from the state.
    void refresh();

signals:
    /// apply() (a stop, or the command line) has shown everything it asked for.
    void shown();

protected:
    void closeEvent(QCloseEvent* e) override;

private:
    void buildToolbars();
    void buildTourBar();
    /// A label naming a toolbar box.
    QLabel* toolbarLabel(const QString& text);
    /// The rest of apply(), once its rays are traced.
    bool finishApply(const GuiOptions& o, bool wait);
    /// Zoom and focus rectangle of `o` on the views (fitted when it gives neither).
    void frameViews(const GuiOptions& o);
    /// Keeps room beside `view`'s image for the caption and key `painter` last drew.
    void keepLegendBeside(ImageView* view, const OverlayPainter& painter);
    void buildDocks();
    void onBusyChanged(bool busy);
    void onPlayTick();
    void updateControls();
    int beamPath() const;
    void refreshCompare();
    /// The selection as it applies to the compared render.
    rc::Selection compareSelection() const;
    /// The image size and choices a new render gets.
    rc::RenderOptions effectiveOptions() const;
    /// Repaints the views and rebuilds the scene view's sketch (after a selection change).
    void viewsChanged();
    double heatmapTop() const;
    void startCompare();

    std::optional<GuiOptions> pending_;  ///< apply()'s rest, waiting for its rays
    bool pendingRun_ = false;            ///< its run to the next miss or deferral has started
    /// The next part of pending_: its run to a miss or deferral, else the rest of apply().
    void continuePending();
    rc::Tour tour_;
    std::vector<GuiOptions> stops_;
    int stop_ = 0;
    QToolBar* tourBar_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* progressCancel_ = nullptr;
    QComboBox* stopBox_ = nullptr;
    QLabel* tourCaption_ = nullptr;
    QSplitter* split_ = nullptr;
    QString sceneSpec_;  ///< as loadScene() was given it
    rc::MissReason missFilter_ = rc::MissReason::None;
    bool workerSessions_ = false;
    std::int64_t stepsOnReset_ = 0;  ///< apply(): rays the worker traces after building the render
    std::vector<QDockWidget*> docks_;  ///< in panelNames()' order
    QList<QDockWidget*> shownBeforePresent_, raisedBeforePresent_;
    bool fontsBeforePresent_ = false, largeFonts_ = false, presenting_ = false;

    SessionController controller_;
    SessionController compare_;
    std::optional<CompareChoice> compareChoice_;
    OverlayPainter comparePainter_;
    ImageView* compareView_ = nullptr;
    SceneView* sceneView_ = nullptr;
    bool followingView_ = false;  ///< one view is copying the other's zoom and pan
    QComboBox* compareBox_ = nullptr;
    QAction* sceneViewAct_ = nullptr;
    std::shared_ptr<const rc::Scene> scene_;
    rc::RenderOptions options_;
    int sizeChoice_ = 0;  ///< 0: the scene's size, else the longer side
    Overlays overlays_;
    Heatmap heatmap_ = Heatmap::None;
    rc::Selection selection_;
    OverlayPainter overlayPainter_;
    ErrorReporter reportError_;
    QTimer playTimer_;
    double playCredit_ = 0.0;

    ImageView* view_ = nullptr;
    RayTreePanel* rayTree_ = nullptr;
    class CacheTreePanel* cacheTree_ = nullptr;
    StatsPanel* stats_ = nullptr;
    EventLogPanel* eventLog_ = nullptr;
    ObjectsPanel* objects_ = nullptr;
    QComboBox *sceneBox_ = nullptr, *cacheBox_ = nullptr, *orderBox_ = nullptr, *sizeBox_ = nullptr, *accelBox_ = nullptr,
              *heatmapBox_ = nullptr;
    QCheckBox *cylinderBox_ = nullptr, *hullBox_ = nullptr, *frontierBox_ = nullptr, *missesBox_ = nullptr,
              *gridBox_ = nullptr, *legendBox_ = nullptr, *samplesBox_ = nullptr;
    QAction *presentAct_ = nullptr, *largeAct_ = nullptr;
    /// The toolbar actions of the overlay boxes: hidden when the session cannot use them
    QAction *cylinderAct_ = nullptr, *hullAct_ = nullptr, *frontierAct_ = nullptr, *missesAct_ = nullptr;
    QSlider* speed_ = nullptr;
    QLabel* speedLabel_ = nullptr;
    QAction *nextDeferralAct_ = nullptr, *goToAct_ = nullptr;
    QAction *stepRayAct_ = nullptr, *stepPixelAct_ = nullptr, *nextMissAct_ = nullptr, *playAct_ = nullptr,
            *runAct_ = nullptr, *cancelAct_ = nullptr, *resetAct_ = nullptr, *backAct_ = nullptr,
            *openAct_ = nullptr;
};

}  // namespace rcgui
