#pragma once
/// \file
/// \brief How the window lays out its views: room beside an image for its caption and
/// key, and the shares of the side-by-side views.
#include <QList>
#include <QString>

namespace rc { class SessionState; }

namespace rcgui {

class ImageView;
class OverlayPainter;

/// Keeps room beside `view`'s image for the caption and key `painter` last drew.
void keepLegendBeside(ImageView* view, const OverlayPainter& painter);

/// The splitter's sizes of the image, the compared image and the scene view: the shown
/// ones share the width equally, the hidden ones get none.
QList<int> paneSizes(bool compared, bool sceneShown);

/// The hover text of pixel (x, y) of a render (empty outside it or without one).
QString pixelTooltip(const rc::SessionState* s, int x, int y);

}  // namespace rcgui
