#pragma once
/// \file
/// \brief The scene seen from the side: objects, lights, the eye, the ray tree of the
/// pixel in focus, its cylinder of safety and blocker hull, in an orthographic view
/// across the ray (the paper's Figure 2), down the ray (Figure 1), from above or in front.
#include <optional>
#include <vector>

#include <QPolygonF>
#include <QString>
#include <QPixmap>
#include <QWidget>

#include "gui_options.h"
#include "view/ray_focus.h"
#include "view/sample_fan.h"

class QComboBox;
class QCheckBox;

namespace rcgui {

/// What the scene view draws, copied out of a SessionState (the view keeps no pointer
/// into a render, which a worker may be changing).
struct SceneSketch {
    struct Body {
        int id = 0;
        rc::Shape shape = rc::Shape::Sphere;
        rc::Sphere bound;
        std::vector<rc::Vec3> polygon;  ///< polygons: their vertices
    };
    struct Segment {
        rc::Vec3 a{0.0}, b{0.0};
        rc::RayKind kind = rc::RayKind::Primary;
        bool focus = false;  ///< the ray in focus
    };
    std::vector<Body> bodies;
    std::vector<rc::Vec3> lights;
    rc::Vec3 eye{0.0}, forward{0, 0, -1}, up{0, 1, 0};
    rc::Sphere bound;                 ///< the scene's bounding sphere
    std::vector<Segment> rays;        ///< the ray tree of the pixel in focus
    std::optional<rc::RayFocus> focus;    ///< the ray in focus
    QString focusLabel;               ///< its path and pixel, e.g. "eye/reflection of pixel (3,4)"
    rc::FocusHull hull;
    rc::FocusCylinder cylinder;
    bool hasCylinder = false;         ///< the cache keeps cylinders (or none: drawn around the ray)
    int limiter = -1;                 ///< the object nearest the cylinder's axis: it sets the radius
    rc::SampleFan fan;                    ///< the sample rays of the pixel in focus (empty: not asked for)

    /// The sketch of `s` with the ray `sel` puts in focus (and its pixel's sample rays
    /// when `samples`).
    static SceneSketch of(const rc::SessionState& s, const rc::Selection& sel, bool samples = false);
};

/// An orthographic projection: screen x and y, and z towards the viewer.
struct SceneBasis {
    rc::Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    /// The basis of `angle` for `sketch`, turned by `yaw` and `pitch` degrees.
    static SceneBasis of(const SceneSketch& sketch, SceneAngle angle, double yaw, double pitch);
    QPointF project(const rc::Vec3& p) const;  ///< (x, y) in world units, y up
    double depth(const rc::Vec3& p) const;     ///< towards the viewer
};

/// The orthographic outline of the convex hull of two balls: the hull of their discs.
QPolygonF discHull(const QPointF& a, double ra, const QPointF& b, double rb, int samples = 64);

/// The scene view widget. Drag to orbit, wheel to zoom, double-click to reset.
class SceneView : public QWidget {
    Q_OBJECT
public:
    explicit SceneView(QWidget* parent = nullptr);
    void setSketch(SceneSketch sketch);
    const SceneSketch& sketch() const { return sketch_; }
    void setAngle(SceneAngle a);
    SceneAngle angle() const { return angle_; }
    void setOrbit(double yaw, double pitch);
    double yaw() const { return yaw_; }
    double pitch() const { return pitch_; }
    /// Which of the focused ray's shapes are drawn (the overlay toggles).
    void setLayers(bool cylinder, bool hull, bool samples = false);
    /// Frame the whole scene rather than the ray in focus.
    void setWholeScene(bool on);
    /// Where world point `p` is drawn (widget coordinates), in the current framing.
    /// The student's rc::Hull of `a` and `b` (a student build with tutorial 03 open), in widget
    /// coordinates: its section in the view's plane.
    QPolygonF studentHull(const rc::Sphere& a, const rc::Sphere& b) const;
    QPointF toWidget(const rc::Vec3& p) const;
    /// Widget pixels per world unit.
    double scale() const { return scale_; }
    /// The caption drawn at the top.
    const QString& caption() const { return caption_; }
    /// Where the last paint put its labels and its caption box (widget coordinates): the
    /// layout the back-row test reads.
    const std::vector<QRectF>& labelRects() const { return labelRects_; }
    const QRectF& captionRect() const { return captionRect_; }
    /// Where the scene is drawn (clipped): the view below the caption.
    QRectF drawingRect() const;

    QSize sizeHint() const override { return {520, 520}; }

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseDoubleClickEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

private:
    void frame();
    SceneSketch sketch_;
    std::uint64_t sketchSerial_ = 0;  ///< sketches whose bodies' layer differs, for that layer
    QPixmap bodies_;                  ///< the scene's objects as last drawn
    std::vector<double> bodiesKey_;   ///< what they were drawn for (sketch, size, projection)
    /// Draws the objects on screen, farthest first; potential blockers, the target and
    /// the ray's objects in bold.
    void paintBodies(QPainter& p, const std::vector<bool>& blocker, int target, double lw) const;
    /// The bodies from their layer, drawn again only when the sketch or the view changed.
    void paintBodiesLayer(QPainter& p, double lw);
    /// The blocker hull, its blockers, origin and target; the cylinder of safety.
    void paintFocusShapes(QPainter& p, double lw) const;
    /// The sample rays of the pixel in focus and the lights' spheres (when Samples is on).
    void paintFan(QPainter& p, double lw) const;
    /// The ray tree (only the ray in focus under a fan), the lights, the eye, the ray's axis.
    void paintRays(QPainter& p, bool fan, double lw) const;
    /// The caption's lines: what is seen, with the sizes the paper's figures compare.
    QStringList captionLines(bool fan) const;
    /// The labels of the eye, lights, Figure 1's and Figure 2's shapes (fills labelRects_).
    void paintLabels(QPainter& p, double lw);
    /// One label near `at`, clear of captionRect_ and the labels placed before it (none if no room).
    void placeLabel(QPainter& p, const QPointF& at, const QString& t, const QColor& c);
    QRectF discOf(const rc::Sphere& s) const;
    QPolygonF hullOf(const rc::Sphere& a, const rc::Sphere& b) const;
    SceneAngle angle_ = SceneAngle::Side;
    double yaw_ = 0.0, pitch_ = 0.0, zoom_ = 1.0;
    bool whole_ = false;
    bool cylinderShown_ = true, hullShown_ = true, samplesShown_ = false;
    SceneBasis basis_;
    double scale_ = 1.0;
    QPointF centre_;  ///< world (x, y) at the middle of the drawing area
    QString caption_;
    std::vector<QRectF> labelRects_;
    QRectF captionRect_;
    QComboBox* angleBox_ = nullptr;
    QCheckBox* wholeBox_ = nullptr;
    QPointF lastPos_;
};

}  // namespace rcgui
