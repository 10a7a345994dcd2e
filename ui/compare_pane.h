#pragma once
/// \file
/// \brief Compare mode: a second render, with another cache and order, beside the first
/// and in lockstep with it.
#include <optional>

#include <QObject>

#include "gui_options.h"
#include "overlay_painter.h"
#include "session_controller.h"

class QComboBox;

namespace rcgui {

class ImageView;
class MainWindow;

/// The compared render, its view and its painter: the same step count, overlays,
/// selection (by pixel and path) and heatmap scale as the window's render.
class ComparePane : public QObject {
    Q_OBJECT
public:
    explicit ComparePane(MainWindow& window);
    ~ComparePane() override;

    /// The toolbar's box, kept showing the choice.
    void setBox(QComboBox* box) { box_ = box; }
    /// See MainWindow::setCompare.
    bool set(const QString& spec, QString& error);
    /// apply()'s choice: the view shown or hidden, the render dropped when there is none
    /// (start() builds it).
    void choose(const std::optional<CompareChoice>& choice);
    /// Builds the compared render from the window's scene and choices (a render made
    /// ahead with them is taken as it is).
    void start();
    /// See MainWindow::syncCompare.
    void sync(bool now);
    /// Shows the compared render (syncing it first), its caption and statistics.
    void refresh();
    /// The selection as it applies to the compared render.
    rc::Selection selection() const;
    /// The heatmap scale both renders share: the larger of their own (0: each its own).
    double heatmapTop() const;
    /// Stops the compared render's worker and waits for it.
    void stop();

    bool on() const { return choice_.has_value(); }
    const std::optional<CompareChoice>& choice() const { return choice_; }
    SessionController& controller() { return controller_; }
    ImageView* view() const { return view_; }
    OverlayPainter& painter() { return painter_; }
    const OverlayPainter& painter() const { return painter_; }

private:
    /// The view's overlays, key and tooltips, and its clicks selecting in the window.
    void hookView();
    /// `from`'s zoom and pan copied to `to`: the same pixels side by side.
    void follow(ImageView* from, ImageView* to);
    /// The box shows the choice.
    void showChoice();

    MainWindow& w_;
    SessionController controller_;
    std::optional<CompareChoice> choice_;
    OverlayPainter painter_;
    ImageView* view_ = nullptr;
    QComboBox* box_ = nullptr;
    bool following_ = false;  ///< one view is copying the other's zoom and pan
};

}  // namespace rcgui
