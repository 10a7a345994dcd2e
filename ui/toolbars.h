#pragma once
/// \file
/// \brief The window's toolbars: the render's choices (scene, cache, order, search, size,
/// compare), stepping (ray, pixel, miss, deferral, play, run, back) and what is shown
/// (overlays, heatmap, fonts, presentation, scene view).
#include <QObject>
#include <QStringList>

#include "overlay_options.h"
#include "render/render_session.h"
#include "view/session_state.h"

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QToolBar;

namespace rcgui {

class MainWindow;

/// The folder of NFF scenes the Scene menu lists: $RAYCACHE_SCENES, else the project's
/// scenes/ as configured at build time.
QString scenesFolder();

/// The three toolbars of a window and the boxes and actions on them. Each box or action
/// calls the window's public slot of the same meaning.
class Toolbars : public QObject {
    Q_OBJECT
public:
    explicit Toolbars(MainWindow& window);

    /// Boxes checked as `o` says (without calling back).
    void showOverlays(const Overlays& o);
    /// The boxes showing these choices (without calling back).
    void showChoices(const rc::RenderOptions& o, int sizeChoice);
    void showHeatmap(Heatmap h);
    void showSceneView(bool on);
    /// Enables what can run now, and offers only the overlays `s`'s cache and order can draw.
    void update(bool busy, const rc::SessionState* s, bool playing);
    /// Labels of the overlay boxes offered.
    QStringList offeredOverlays() const;
    /// The Scene and Cache boxes' entries.
    QStringList sceneChoices() const;
    QStringList cacheChoices() const;
    QString cacheShown() const;
    /// The Play speed chosen.
    double raysPerSecond() const;
    /// Play's button checked as `on`: true when it was not, and has called the window's
    /// setPlaying() again through its toggle; else it says Pause while playing.
    bool showPlaying(bool on);

    QComboBox* sceneBox() const { return scene_; }
    QComboBox* cacheBox() const { return cache_; }
    QComboBox* compareBox() const { return compare_; }
    QAction* presentAction() const { return presentAct_; }
    QAction* largeFontsAction() const { return largeAct_; }

private:
    /// A label naming a toolbar box.
    QLabel* label(const QString& text);
    /// A box of the render toolbar, `name` labelling it.
    QComboBox* box(QToolBar* bar, const QString& name);
    void buildRender();
    /// The render toolbar's boxes of scene and cache.
    void buildSceneAndCache(QToolBar* bar);
    /// The render toolbar's boxes of order, search, size and compare.
    void buildChoices(QToolBar* bar);
    void buildStep();
    /// The step toolbar's play button, speed and run to end.
    void buildPlay(QToolBar* bar);
    void buildShow();
    /// The show toolbar's check box of one overlay.
    QCheckBox* overlayBox(QToolBar* bar, const QString& label, const QString& tip, bool Overlays::*field);
    /// The show toolbar's fonts, presentation, scene view and fit.
    void buildViewActions(QToolBar* bar);

    MainWindow& w_;
    QComboBox *scene_ = nullptr, *cache_ = nullptr, *order_ = nullptr, *size_ = nullptr, *accel_ = nullptr,
              *heatmap_ = nullptr, *compare_ = nullptr;
    QCheckBox *cylinderBox_ = nullptr, *hullBox_ = nullptr, *frontierBox_ = nullptr, *missesBox_ = nullptr,
              *gridBox_ = nullptr, *legendBox_ = nullptr, *samplesBox_ = nullptr;
    QAction *presentAct_ = nullptr, *largeAct_ = nullptr, *sceneViewAct_ = nullptr;
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
