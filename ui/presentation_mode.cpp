#include "presentation_mode.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QToolBar>

#include "overlay_options.h"
#include "panels.h"
#include "stats_panel.h"

namespace rcgui {

namespace {
// Points of the text: large fonts for a projector, larger still when presenting
constexpr double kNormalPoints = 10.0, kLargePoints = 16.0, kPresentingPoints = 20.0;
// The toolbars' labels stay small: on a projector the boxes they name must fit a row
constexpr double kToolbarLabelPoints = 10.0, kLargeToolbarLabelPoints = 11.0;
// Overlay lines thicken with the text, so that they read from as far away
constexpr double kLargeLineScale = 1.8, kPresentingLineScale = 2.2;
}  // namespace

PresentationMode::PresentationMode(QMainWindow& window, Panels& panels, Overlays& overlays)
    : QObject(&window), window_(window), panels_(panels), overlays_(overlays) {}

void PresentationMode::setPresenting(bool on) {
    if (presentAct_ && presentAct_->isChecked() != on) {
        presentAct_->setChecked(on);  // comes back here through toggled()
        return;
    }
    // Leaving brings back the panels that were shown, the tabs that were raised and the
    // fonts that were chosen
    if (on == presenting_) return;
    presenting_ = on;
    const std::vector<QDockWidget*>& docks = panels_.docks();
    if (on) {
        shownBefore_.clear();
        raisedBefore_.clear();
        for (QDockWidget* d : docks) {
            if (!d->isHidden()) shownBefore_ << d;
            if (d->isVisible()) raisedBefore_ << d;  // on screen: the front tab of its group
        }
        fontsBefore_ = largeFonts_;
    }
    for (QDockWidget* d : docks) d->setVisible(on ? false : shownBefore_.contains(d));
    if (!on)
        for (QDockWidget* d : raisedBefore_) d->raise();
    for (QToolBar* t : window_.findChildren<QToolBar*>())
        if (t->objectName() == "render") t->setVisible(!on);
    // Presenting: larger still than large fonts (setLargeFonts reads presenting_)
    setLargeFonts(on || fontsBefore_);
}

void PresentationMode::showPanels(const QStringList& names) {
    if (!presenting_) {
        panels_.show(names);
        return;
    }
    // Presenting: the stop's panels are what leaving presentation brings back
    const QList<QDockWidget*> on = panels_.docksNamed(names);
    for (QDockWidget* d : panels_.docks()) {
        shownBefore_.removeAll(d);
        raisedBefore_.removeAll(d);
    }
    shownBefore_ << on;
    raisedBefore_ << on;
}

void PresentationMode::setLargeFonts(bool on) {
    largeFonts_ = on;
    if (largeAct_ && largeAct_->isChecked() != on) {
        const QSignalBlocker b(largeAct_);
        largeAct_->setChecked(on);
    }
    panels_.stats()->setLargeFonts(on);
    overlays_.lineScale = presenting_ ? kPresentingLineScale : on ? kLargeLineScale : 1.0;
    QFont f = QApplication::font();
    f.setPointSizeF(presenting_ ? kPresentingPoints : on ? kLargePoints : kNormalPoints);
    QApplication::setFont(f);
    for (QWidget* w : window_.findChildren<QWidget*>()) w->setFont(f);
    QFont label = f;
    label.setPointSizeF(on ? kLargeToolbarLabelPoints : kToolbarLabelPoints);
    for (QLabel* l : window_.findChildren<QLabel*>("toolbarLabel")) l->setFont(label);
    // Tighter buttons, so that each toolbar keeps to one row of a 1280-pixel screen
    for (QToolBar* t : window_.findChildren<QToolBar*>())
        t->setStyleSheet(on ? "QToolButton { padding: 1px 2px; margin: 0px; }" : QString());
    emit fontsChanged();
}

}  // namespace rcgui
