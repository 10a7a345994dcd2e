#include "view_layout.h"

#include <algorithm>
#include <cmath>

#include <QTimer>

#include "heatmap_builder.h"
#include "image_view.h"
#include "overlay_painter.h"
#include "view/session_state.h"

namespace rcgui {

namespace {
// The caption and key may take at most this share of the view's width from a fitted image
constexpr double kLegendShareOfView = 1.0 / 3.0;
// Changes of the room kept smaller than this many pixels are not worth a relayout
constexpr double kLegendRoomSlack = 8.0;
// QSplitter divides its width in proportion to the sizes: equal shares, one unit each
constexpr int kEqualShare = 1000;
}  // namespace

void keepLegendBeside(ImageView* view, const OverlayPainter& painter) {
    // The caption and key go beside the fitted image, never over it: the view keeps room
    // for them, shrinking the image by at most a third of the view's width (a wider key
    // wraps its lines)
    const QSizeF image = view->image().size();
    const double fitted = image.isEmpty() ? 0.0 : image.width() * std::min(view->width() / image.width(), view->height() / image.height());
    const double room = std::max(0.0, view->width() - fitted);
    const double want = std::min(painter.legendWidth(), std::max(room, view->width() * kLegendShareOfView));
    if (std::abs(want - view->reserve()) > kLegendRoomSlack)
        QTimer::singleShot(0, view, [view, want] { view->setReserve(want); });
}

QList<int> paneSizes(bool compared, bool sceneShown) {
    return {kEqualShare, compared ? kEqualShare : 0, sceneShown ? kEqualShare : 0};
}

QString pixelTooltip(const rc::SessionState* s, int x, int y) {
    if (!s || x < 0 || y < 0 || x >= s->width() || y >= s->height()) return {};
    const rc::TraceRecorder& rec = s->recorder();
    const int px = y * s->width() + x;
    if (rec.firstVisit(px) < 0) return QString("pixel (%1,%2): not traced yet").arg(x).arg(y);
    QString t = QString("pixel (%1,%2): %3 tests, %4 hits, %5 misses, first ray at step %6")
                    .arg(x).arg(y).arg(rec.testsAt(px)).arg(rec.hitsAt(px)).arg(rec.missesAt(px))
                    .arg(rec.firstVisit(px));
    if (rec.missReasonAt(px) != rc::MissReason::None)
        t += QString(", first miss: %1").arg(QString::fromUtf8(rc::toString(rec.missReasonAt(px)).data()));
    const std::optional<double> rate = HeatmapBuilder::hitRate(*s, px);
    t += rate ? QString(", hit rate %1% (%2 of %3 lookups)")
                    .arg(100.0 * *rate, 0, 'f', 1).arg(rec.hitsAt(px)).arg(rec.hitsAt(px) + rec.missesAt(px))
              : QString(", hit rate: no cache lookups");
    return t;
}

}  // namespace rcgui
