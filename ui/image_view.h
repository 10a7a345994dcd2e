#pragma once
/// \file
/// \brief The central view: the image (or a heatmap) with zoom, pan, a pixel grid at
/// high zoom, overlays, and clicks mapped to image pixels.
#include <functional>
#include <optional>

#include <QImage>
#include <QWidget>

namespace rcgui {

/// Shows an image scaled by `zoom()` and shifted by `pan()`: image point p appears at
/// widget point pan + zoom * p. Wheel zooms about the cursor, dragging pans, a click
/// (press and release without moving) selects a pixel.
class ImageView : public QWidget {
    Q_OBJECT
public:
    /// Paints overlays in image coordinates; `scale` is widget pixels per image pixel.
    using OverlayHook = std::function<void(QPainter&, double scale)>;
    /// Paints in widget coordinates, above everything (captions, legends).
    using LegendHook = std::function<void(QPainter&, const QRectF& area)>;

    explicit ImageView(QWidget* parent = nullptr);

    void setImage(const QImage& image);
    const QImage& image() const { return image_; }
    void setOverlayHook(OverlayHook hook) { overlay_ = std::move(hook); }
    void setLegendHook(LegendHook hook) { legend_ = std::move(hook); }
    /// Text of the hover tooltip of image pixel (x, y) (empty: none).
    using TooltipHook = std::function<QString(int x, int y)>;
    void setTooltipHook(TooltipHook hook) { tooltip_ = std::move(hook); }
    /// The tooltip the view shows over image pixel (x, y).
    QString tooltipAt(int x, int y) const { return tooltip_ ? tooltip_(x, y) : QString(); }
    void setGridEnabled(bool on);

    double zoom() const { return zoom_; }
    QPointF pan() const { return pan_; }
    /// Zooms by `factor` keeping widget point `anchor` over the same image point.
    void zoomAt(double factor, const QPointF& anchor);
    void setZoom(double zoom, const QPointF& pan);
    /// Fits the whole image in the widget.
    void fit();
    /// Fits image rectangle `r` (pixels) to the view, centred; it stays fitted as the view
    /// is resized, until the user zooms or pans. An empty `r` fits the whole image.
    void fitRect(const QRectF& r);
    /// Pixels kept free at the right when fitting: room for the key beside the image.
    void setReserve(double pixels);
    double reserve() const { return reserve_; }
    /// Where the image shows in widget coordinates: its rectangle, less the reserved
    /// strip (the image is not drawn there, even zoomed in), so a key beside it stays off it.
    QRectF shownImageRect() const;

    QPointF imageToWidget(const QPointF& p) const { return pan_ + zoom_ * p; }
    QPointF widgetToImage(const QPointF& w) const { return (w - pan_) / zoom_; }
    /// The image pixel under a widget point, or nothing outside the image.
    std::optional<QPoint> pixelAt(const QPointF& widgetPoint) const;

    QSize sizeHint() const override { return {800, 700}; }

signals:
    void pixelClicked(int x, int y);
    void cleared();
    /// The zoom or pan changed (by the user, fit() or setZoom()).
    void viewMoved();

protected:
    void paintEvent(QPaintEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    bool event(QEvent* e) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void resizeEvent(QResizeEvent*) override;
    void keyPressEvent(QKeyEvent*) override;

private:
    QImage image_;
    OverlayHook overlay_;
    LegendHook legend_;
    TooltipHook tooltip_;
    double zoom_ = 1.0;
    QPointF pan_{0, 0};
    bool fitted_ = false;  ///< follows the widget's size until the user zooms or pans
    QRectF focus_;         ///< the rectangle fitted (empty: the whole image)
    double reserve_ = 0.0; ///< see setReserve()
    void refit();
    bool grid_ = true;
    bool dragging_ = false;
    QPointF pressPos_, lastPos_;
};

}  // namespace rcgui
