#pragma once
/// \file
/// \brief Presentation mode and large fonts: a lecture hall's window, the panels hidden
/// and the text enlarged, and the way back to the window as it was.
#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;

namespace rcgui {

class Panels;
struct Overlays;

/// Presenting, large fonts, and what leaving presentation brings back.
class PresentationMode : public QObject {
    Q_OBJECT
public:
    /// `overlays` gets the line scale the fonts ask for.
    PresentationMode(QMainWindow& window, Panels& panels, Overlays& overlays);

    /// The toolbar's actions, kept checked as the mode is.
    void setActions(QAction* present, QAction* large) { presentAct_ = present, largeAct_ = large; }
    /// The panels and the render toolbar hidden, fonts larger still than large fonts.
    void setPresenting(bool on);
    bool presenting() const { return presenting_; }
    /// Large fonts for a projector (larger still while presenting).
    void setLargeFonts(bool on);
    /// Shows the docks `names` lists; while presenting, they are what leaving brings back.
    void showPanels(const QStringList& names);

signals:
    /// The fonts changed: the picture's text and key are to be drawn again.
    void fontsChanged();

private:
    QMainWindow& window_;
    Panels& panels_;
    Overlays& overlays_;
    QAction *presentAct_ = nullptr, *largeAct_ = nullptr;
    QList<QDockWidget*> shownBefore_, raisedBefore_;
    bool fontsBefore_ = false, largeFonts_ = false, presenting_ = false;
};

}  // namespace rcgui
