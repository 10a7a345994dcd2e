#include "image_view.h"

#include <algorithm>
#include <cmath>

#include <QHelpEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>

namespace rcgui {

ImageView::ImageView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(false);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 200);
    setAutoFillBackground(false);
}

void ImageView::setImage(const QImage& image) {
    const bool resized = image.size() != image_.size();
    image_ = image;
    if (resized) {
        fitted_ = true;
        focus_ = QRectF();
    }
    if (fitted_) refit();
    update();
}

void ImageView::setGridEnabled(bool on) {
    grid_ = on;
    update();
}

void ImageView::fit() {
    fitted_ = true;
    focus_ = QRectF();
    if (image_.isNull() || width() <= 0 || height() <= 0) return;
    const double usable = std::max(50.0, width() - reserve_);
    zoom_ = std::min(usable / image_.width(), double(height()) / image_.height());
    pan_ = QPointF((usable - zoom_ * image_.width()) / 2, (height() - zoom_ * image_.height()) / 2);
    update();
    emit viewMoved();
}

QRectF ImageView::shownImageRect() const {
    const QRectF whole(imageToWidget(QPointF(0, 0)), imageToWidget(QPointF(image_.width(), image_.height())));
    if (reserve_ <= 0.0) return whole;
    return whole.intersected(QRectF(0, 0, std::max(50.0, width() - reserve_), height()));
}

void ImageView::setReserve(double pixels) {
    reserve_ = std::max(0.0, pixels);
    if (fitted_) refit();
}

void ImageView::fitRect(const QRectF& r) {
    if (r.isEmpty()) return fit();
    fitted_ = true;
    focus_ = r;
    if (width() <= 0 || height() <= 0) return;
    const double usable = std::max(50.0, width() - reserve_);
    zoom_ = std::clamp(std::min(usable / r.width(), double(height()) / r.height()), 0.05, 200.0);
    pan_ = QPointF(usable / 2.0, height() / 2.0) - zoom_ * r.center();
    update();
    emit viewMoved();
}

void ImageView::zoomAt(double factor, const QPointF& anchor) {
    const QPointF under = widgetToImage(anchor);
    zoom_ = std::clamp(zoom_ * factor, 0.05, 200.0);
    pan_ = anchor - zoom_ * under;
    fitted_ = false;
    update();
    emit viewMoved();
}

void ImageView::setZoom(double zoom, const QPointF& pan) {
    zoom_ = zoom;
    pan_ = pan;
    fitted_ = false;
    update();
    emit viewMoved();
}

std::optional<QPoint> ImageView::pixelAt(const QPointF& widgetPoint) const {
    const QPointF p = widgetToImage(widgetPoint);
    const int x = int(std::floor(p.x())), y = int(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= image_.width() || y >= image_.height()) return std::nullopt;
    return QPoint(x, y);
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(48, 48, 52));
    if (image_.isNull()) return;
    p.save();
    // Nothing of the image in the reserved strip: the key goes there
    if (reserve_ > 0.0) p.setClipRect(QRectF(0, 0, std::max(50.0, width() - reserve_), height()));
    p.translate(pan_);
    p.scale(zoom_, zoom_);
    // Nearest-neighbour scaling: pixels stay square at high zoom
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QPointF(0, 0), image_);
    if (grid_ && zoom_ >= 8.0) {
        const QPointF tl = widgetToImage(QPointF(0, 0)), br = widgetToImage(QPointF(width(), height()));
        const int x0 = std::max(0, int(tl.x())), x1 = std::min(image_.width(), int(br.x()) + 1);
        const int y0 = std::max(0, int(tl.y())), y1 = std::min(image_.height(), int(br.y()) + 1);
        QPen pen(QColor(128, 128, 128, 140), 1);
        pen.setCosmetic(true);
        p.setPen(pen);
        for (int x = x0; x <= x1; ++x) p.drawLine(QPointF(x, y0), QPointF(x, y1));
        for (int y = y0; y <= y1; ++y) p.drawLine(QPointF(x0, y), QPointF(x1, y));
    }
    if (overlay_) overlay_(p, zoom_);
    p.restore();
    if (legend_) legend_(p, QRectF(rect()));
}

void ImageView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    zoomAt(std::pow(1.25, steps), e->position());
    e->accept();
}

void ImageView::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::RightButton) {
        emit cleared();
        return;
    }
    pressPos_ = lastPos_ = e->position();
    dragging_ = false;
}

void ImageView::mouseMoveEvent(QMouseEvent* e) {
    if (!(e->buttons() & (Qt::LeftButton | Qt::MiddleButton))) return;
    if (!dragging_ && (e->position() - pressPos_).manhattanLength() > 4) dragging_ = true;
    if (dragging_) {
        pan_ += e->position() - lastPos_;
        fitted_ = false;
        update();
        emit viewMoved();
    }
    lastPos_ = e->position();
}

bool ImageView::event(QEvent* e) {
    if (e->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(e);
        const auto px = pixelAt(QPointF(help->pos()));
        const QString text = px ? tooltipAt(px->x(), px->y()) : QString();
        if (text.isEmpty()) QToolTip::hideText();
        else QToolTip::showText(help->globalPos(), text, this);
        return true;
    }
    return QWidget::event(e);
}

void ImageView::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton && !dragging_) {
        // A click on a pixel selects it; outside the image, it lets the selection go
        if (auto px = pixelAt(e->position())) emit pixelClicked(px->x(), px->y());
        else emit cleared();
    }
    dragging_ = false;
}

void ImageView::resizeEvent(QResizeEvent*) {
    if (fitted_) refit();
}

void ImageView::refit() {
    if (focus_.isEmpty()) fit();
    else fitRect(focus_);
}

void ImageView::keyPressEvent(QKeyEvent* e) {
    if (e->key() == Qt::Key_Escape) emit cleared();
    else if (e->key() == Qt::Key_0 || e->key() == Qt::Key_F) fit();
    else if (e->key() == Qt::Key_Plus || e->key() == Qt::Key_Equal) zoomAt(1.5, QPointF(width() / 2.0, height() / 2.0));
    else if (e->key() == Qt::Key_Minus) zoomAt(1 / 1.5, QPointF(width() / 2.0, height() / 2.0));
    else QWidget::keyPressEvent(e);
}

}  // namespace rcgui
