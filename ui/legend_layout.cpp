#include "legend_layout.h"

#include <algorithm>

namespace rcgui {

std::vector<QRectF> LegendLayout::boxes() const {
    std::vector<QRectF> out;
    for (const QRectF& r : {info, key, bar})
        if (!r.isEmpty()) out.push_back(r);
    return out;
}

LegendLayout layOutLegend(const QRectF& area, const QRectF& picture, const LegendBlock& info, const LegendBlock& key,
                          const LegendBlock& bar) {
    LegendLayout out;
    out.picture = picture.intersected(area);
    // The column: the strip beside the picture with more room (the whole view without one)
    const double rightRoom = area.right() - std::max(area.left(), out.picture.right());
    const double leftRoom = std::min(area.right(), out.picture.left()) - area.left();
    if (out.picture.isEmpty()) out.column = area;
    else if (rightRoom >= leftRoom) out.column = QRectF(out.picture.right(), area.top(), rightRoom, area.height());
    else out.column = QRectF(area.left(), area.top(), leftRoom, area.height());
    const QRectF inside = out.column.adjusted(kLegendGap, kLegendGap, -kLegendGap, -kLegendGap);
    out.fits = inside.width() > 0.0 && inside.height() > 0.0;
    if (!out.fits) return out;
    // One box under the other, from the top; a box that runs past the bottom is cut there
    double top = inside.top();
    const auto place = [&](const LegendBlock& b) {
        if (b.empty() || top >= inside.bottom()) {
            if (!b.empty()) out.fits = false;
            return QRectF();
        }
        const double width = std::min(b.naturalWidth, inside.width());
        if (width < b.minWidth) out.fits = false;
        const double height = b.height(width);
        const QRectF box(inside.left(), top, width, std::min(height, inside.bottom() - top));
        if (box.height() < height) out.fits = false;
        top = box.bottom() + kLegendGap;
        return box;
    };
    out.info = place(info);
    out.key = place(key);
    out.bar = place(bar);
    return out;
}

QFont legendFont(const QFont& widgetFont, double scale) {
    // Points to pixels at 96 per inch, the offscreen platform's and most desktops' resolution
    constexpr double kPixelsPerPoint = 96.0 / 72.0;
    QFont f = widgetFont;
    const double points = widgetFont.pointSizeF();
    const double pixels = points > 0.0 ? points * kPixelsPerPoint : double(widgetFont.pixelSize());
    f.setPixelSize(std::max(1, int(std::lround(pixels * scale))));
    return f;
}

}  // namespace rcgui
