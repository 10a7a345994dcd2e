#pragma once
/// \file
/// \brief Where an image view's info box, key and colour bar go: one rule, computed once
/// per paint, that keeps them beside the picture and off each other.
#include <functional>
#include <vector>

#include <QFont>
#include <QRectF>

namespace rcgui {

/// One box to lay out, measured by the painter in the font it will draw with.
struct LegendBlock {
    double naturalWidth = 0.0;  ///< its width with no line wrapped (0: no box)
    double minWidth = 0.0;      ///< narrower, it cannot be drawn whole (a colour bar's five values)
    std::function<double(double width)> height;  ///< its height at a width, lines wrapped
    bool empty() const { return naturalWidth <= 0.0; }
};

/// The rectangles an image view paints, in widget coordinates.
struct LegendLayout {
    QRectF picture;  ///< where the picture's drawn content shows (the image, less the reserved strip)
    QRectF column;   ///< the strip beside the picture that holds the boxes
    QRectF info;     ///< the info box: scene, cache, order, step, the ray in focus (empty: none)
    QRectF key;      ///< the key of the overlays' colours (empty: none)
    QRectF bar;      ///< the heatmap's colour bar, its title and values (empty: none)
    bool fits = false;        ///< every box is whole inside the column
    double lineHeight = 0.0;  ///< the spacing of the boxes' lines as drawn on the paint device, in its pixels
    /// The boxes laid out (the non-empty ones of info, key and bar).
    std::vector<QRectF> boxes() const;
};

/// Gap between a box and the picture, the view's edge or the next box (widget pixels).
inline constexpr double kLegendGap = 8.0;

/// The rule: the boxes go in a column beside the picture, on the side with more room,
/// one under the other from the top of the view, each as wide as its unwrapped lines or
/// the column. Boxes that do not fit are cut at the column's bottom (`fits` is false):
/// never over the picture or each other.
LegendLayout layOutLegend(const QRectF& area, const QRectF& picture, const LegendBlock& info, const LegendBlock& key,
                          const LegendBlock& bar);

/// The font the boxes are drawn in: `widgetFont` at a fixed number of pixels per point,
/// so that a window on any screen and a headless screenshot measure their lines alike
/// (a point size alone follows the screen's dots per inch, which Xvfb and the offscreen
/// platform report differently).
QFont legendFont(const QFont& widgetFont, double scale = 1.0);

}  // namespace rcgui
