#pragma once
/// \file
/// \brief Draws the overlays (cylinder of safety, blocker hull, breadth-first frontier,
/// miss markers, selection) over the image, and their legend.
#include <QImage>
#include <QPainter>

#include "overlay_options.h"
#include "ray_focus.h"

namespace rcgui {

class Projector;

/// What is selected in the window.
struct Selection {
    int pixel = -1;      ///< selected pixel, -1 for none
    int event = -1;      ///< its ray chosen in the ray tree (index into the recorder), -1: its eye ray
    int object = -1;     ///< object highlighted from the objects panel, -1 for none
};

/// Paints overlays for one SessionState. Keeps a few per-pixel layers cached between
/// paints of the same state.
class OverlayPainter {
public:
    /// Paints in image coordinates (the painter maps them to the widget); `scale` is
    /// widget pixels per image pixel, so marks keep a readable size at any zoom.
    void paint(QPainter& p, const SessionState& s, const Overlays& o, const Selection& sel, double scale);
    /// Paints the caption and colour key in widget coordinates inside `area`.
    void paintLegend(QPainter& p, const SessionState& s, const Overlays& o, const Selection& sel,
                     const QRectF& area);

private:
    void paintFocus(QPainter& p, const SessionState& s, const Projector& proj, const RayFocus& f,
                    const Overlays& o);
    void paintCylinder(QPainter& p, const SessionState& s, const Projector& proj, const RayFocus& f);
    void paintHull(QPainter& p, const SessionState& s, const Projector& proj, const RayFocus& f);
    void paintObject(QPainter& p, const SessionState& s, const Projector& proj, int object,
                     const QColor& line, const QColor& fill, double width);
    void paintFrontier(QPainter& p, const SessionState& s, double scale, bool markers);
    void paintMisses(QPainter& p, const SessionState& s, double scale);

    const SessionState* cachedState_ = nullptr;
    std::size_t cachedEvents_ = 0;
    int cachedPath_ = -1;
    QImage regions_;
};

}  // namespace rcgui
