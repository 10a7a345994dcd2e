#pragma once
/// \file
/// \brief The main window: the image view around one SessionController, and the parts it
/// is made of, each a class of its own (Toolbars, ComparePane, TourPlayer,
/// PresentationMode, Panels).
#include <functional>
#include <memory>
#include <optional>

#include <QMainWindow>
#include <QTimer>

#include "gui_options.h"
#include "overlay_options.h"
#include "overlay_painter.h"
#include "compare_pane.h"
#include "panels.h"
#include "presentation_mode.h"
#include "session_controller.h"
#include "stop_applier.h"
#include "toolbars.h"
#include "tour_player.h"
#include "view_layout.h"

class QSplitter;

namespace rcgui {

/// The folder of NFF scenes the Scene menu lists: $RAYCACHE_SCENES, else the project's
/// scenes/ as configured at build time.
QString scenesFolder();


class ComparePane;
class EventLogPanel;
class ImageView;
class Panels;
class Player;
class PresentationMode;
class RaySelector;
class RayTreePanel;
class RunProgress;
class SceneView;
class StatsPanel;
class StopApplier;
class Toolbars;
class TourPlayer;

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
    void reportError(const QString& title, const QString& message) { reportError_(title, message); }
    /// Builds each new render on the worker, so that the window never waits for a large
    /// scene's render to be made, and reads long event logs into the overlay layers over
    /// several paints (the interactive window; tests and screenshots build them here, and
    /// have their state and layers at once). A tour's next stop is then rendered ahead.
    void setWorkerSessions(bool on);
    bool workerSessions() const { return workerSessions_; }
    /// Events of the log each layer reads in one paint of the interactive window.
    static constexpr std::size_t kLayerEventsPerPaint = 100000;

    /// Loads a built-in scene spec or an NFF file and starts a new render of it. On an
    /// error, reports it (file:line:column: message) and keeps the current scene.
    bool loadScene(const QString& spec);
    /// The scene being rendered (null before the first load).
    const rc::Scene* scene() const { return scene_.get(); }
    /// The scene `spec` names: the one rendered when it is that, else loaded (null, and
    /// nothing said, when it cannot be).
    std::shared_ptr<const rc::Scene> sceneFor(const QString& spec) const;
    void setCache(rc::CacheKind k);
    /// The Scene menu's entries.
    QStringList sceneChoices() const { return toolbars_->sceneChoices(); }
    /// The Cache box's entries, and the one it shows.
    QStringList cacheChoices() const { return toolbars_->cacheChoices(); }
    QString cacheShown() const { return toolbars_->cacheShown(); }
    /// Labels of the overlay boxes offered for the current cache and order.
    QStringList offeredOverlays() const { return toolbars_->offeredOverlays(); }
    void setOrder(rc::OrderKind k);
    /// What answers complete searches (linear, grid, bvh).
    void setAccel(rc::AccelKind k);
    /// Distributed ray tracing's samples for the next session (no new session is made).
    void setSampling(const rc::Sampling& s) { options_.shading.sampling = s; }
    /// Image size: the scene's (0), or this longer side (the Size box).
    void setSizeChoice(int longerSide);
    /// Selects pixel (x, y) and its ray at cache-tree path `path` (empty: its eye ray).
    /// On a bad pixel or path, says why in `error` and returns false.
    bool selectRay(int x, int y, const QString& path, QString& error);
    /// Image size; 0 x 0 means the scene's own.
    void setImageSize(int width, int height);
    void setOverlays(const Overlays& o);
    const Overlays& overlays() const { return overlays_; }
    void setHeatmap(Heatmap h);
    Heatmap heatmap() const { return heatmap_; }
    void setLargeFonts(bool on) { presentation_->setLargeFonts(on); }
    /// Presentation mode: the panels and the render toolbar hidden, large fonts.
    void setPresentation(bool on);
    /// Runs a second render with another cache and order beside the first, in lockstep:
    /// the same step count, overlays, selection and heatmap scale. On a bad spec, says
    /// why in `error`, keeps everything as it was and returns false. "off" or "" ends it.
    bool setCompare(const QString& spec, QString& error) { return compare_->set(spec, error); }
    /// The compared render's controller (its state is null when there is none).
    SessionController& compareController() { return compare_->controller(); }
    const std::optional<CompareChoice>& compareChoice() const { return compare_->choice(); }
    ImageView* compareView() const { return compare_->view(); }
    const OverlayPainter& compareOverlayPainter() const { return compare_->painter(); }
    /// Brings the compared render to the first one's step count (on the calling thread
    /// when the gap is small or `now`, else on its worker).
    void syncCompare(bool now = false) { compare_->sync(now); }
    /// Shows or hides the view of the 3D scene.
    void setSceneView(bool on);
    SceneView* sceneView() const { return sceneView_; }
    /// The statistics panel.
    StatsPanel* statsPanel() const { return panels_->stats(); }
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
    /// worker, and the rest applied when it is done, unless `wait`. A render made ahead
    /// for `o` (TourPlayer) is taken as it is. False (and the error reported) on a bad
    /// scene or selection.
    bool apply(const GuiOptions& o, bool wait) { return applier_->apply(o, wait); }
    /// Opens a tour whose stops' options are already read (stopOptions()); shows its strip.
    void setTour(const rc::Tour& tour, std::vector<GuiOptions> stops) { tour_->setTour(tour, std::move(stops)); }
    /// Goes to stop `stop` (from 1) of the tour, as written. False if there is no such stop.
    bool goToStop(int stop, bool wait = false) { return tour_->goToStop(stop, wait); }
    /// The stop shown (from 1; 0: no tour) and how many there are.
    int stop() const { return tour_->stop(); }
    int stopCount() const { return tour_->stopCount(); }
    /// The tour's caption as shown above the image ("" without a tour).
    QString tourCaption() const { return tour_->caption(); }
    /// The tour's player: its stops, and the next stop's render made ahead.
    TourPlayer& tourPlayer() { return *tour_; }
    /// Next miss stops only at misses of this reason (rc::MissReason::None: any).
    void setMissFilter(rc::MissReason r);
    /// Shows the docks `names` lists (panelNames()), raised, and hides the others.
    void showPanels(const QStringList& names) { presentation_->showPanels(names); }
    rc::MissReason missFilter() const { return missFilter_; }
    /// Renders this window has built since it opened, not counting those a tour made
    /// ahead (a stop that takes one made ahead builds none).
    int rendersBuilt() const { return rendersBuilt_; }

    SessionController& controller() { return controller_; }
    Toolbars& toolbars() { return *toolbars_; }
    const OverlayPainter& overlayPainter() const { return overlayPainter_; }
    ImageView* imageView() const { return view_; }
    RayTreePanel* rayTreePanel() const { return panels_->rayTree(); }
    EventLogPanel* eventLogPanel() const { return panels_->eventLog(); }

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
    void nextStop() { goToStop(stop() + 1); }
    void previousStop() { goToStop(stop() - 1); }
    /// Back to the stop as written, after stepping, selecting or toggling from it.
    void restoreStop() { goToStop(stop()); }
    void openSceneDialog();
    /// Refreshes the picture and every panel from the state.
    void refresh();
    /// Repaints the views and rebuilds the scene view's sketch (after a selection change).
    void viewsChanged();

signals:
    /// apply() (a stop, or the command line) has shown everything it asked for.
    void shown();

protected:
    void closeEvent(QCloseEvent* e) override;

private:
    /// The image view, the compared view and the scene view side by side, under the tour's caption.
    void buildViews();
    /// The first render's overlays, key, tooltips and clicks on its view.
    void hookView();
    /// The controller's news: its pictures while it runs, its progress, its end.
    void hookController();
    /// Shows scene_ (given as `spec`) as the Scene box's choice and in the objects panel.
    void showScene(const QString& spec);
    void onBusyChanged(bool busy);
    /// Cancels both renders' workers and waits for them.
    void stopRuns();
    void updateControls();
    int beamPath() const;
    /// The image size and choices a new render gets.
    rc::RenderOptions effectiveOptions() const { return sizedOptions(options_, sizeChoice_, scene_.get()); }

    RunProgress* progress_ = nullptr;
    QSplitter* split_ = nullptr;
    QString sceneSpec_;  ///< as loadScene() was given it
    rc::MissReason missFilter_ = rc::MissReason::None;
    bool workerSessions_ = false;
    std::int64_t stepsOnReset_ = 0;  ///< apply(): rays the worker traces after building the render
    /// apply() in a live window: resetSession() takes a render made ahead, or goes on with
    /// its own when it is the same render
    bool reuseOnReset_ = false;
    int rendersBuilt_ = 0;

    SessionController controller_;
    SceneView* sceneView_ = nullptr;
    std::shared_ptr<const rc::Scene> scene_;
    rc::RenderOptions options_;
    int sizeChoice_ = 0;  ///< 0: the scene's size, else the longer side
    Overlays overlays_;
    Heatmap heatmap_ = Heatmap::None;
    rc::Selection selection_;
    OverlayPainter overlayPainter_;
    ErrorReporter reportError_;
    Player* player_ = nullptr;
    ImageView* view_ = nullptr;

    // The window's parts, each a class of its own (children of the window)
    Panels* panels_ = nullptr;
    Toolbars* toolbars_ = nullptr;
    ComparePane* compare_ = nullptr;
    TourPlayer* tour_ = nullptr;
    PresentationMode* presentation_ = nullptr;
    StopApplier* applier_ = nullptr;
    RaySelector* selector_ = nullptr;
    friend class ComparePane;
    friend class RaySelector;
    friend class StopApplier;
};

}  // namespace rcgui
