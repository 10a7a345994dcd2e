#include "scene_view.h"

#include "legend_layout.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/safety_cylinder.h"
#include "geometry/student_code.h"
#include "palette.h"
#include "projector.h"

namespace rcgui {

namespace {

using palette::withAlpha;

// What the side view calls an object: its shape
const char* shapeName(rc::Shape s) {
    switch (s) {
        case rc::Shape::Sphere: return "sphere";
        case rc::Shape::Polygon: return "polygon";
        case rc::Shape::Cone: return "cone";
    }
    return "object";
}

// The sphere a cylinder's radius is measured against: the sphere itself, or the bounding
// sphere of a polygon or cone
QString boundName(rc::Shape s) {
    return s == rc::Shape::Sphere ? QString("sphere") : QString("bounding sphere of the %1").arg(shapeName(s));
}

QPen pen(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen p(c, width, style, Qt::RoundCap, Qt::RoundJoin);
    p.setCosmetic(true);
    return p;
}

// A unit vector perpendicular to `n`, as close to `want` as can be
rc::Vec3 perpendicular(const rc::Vec3& n, const rc::Vec3& want) {
    rc::Vec3 v = want - n * glm::dot(want, n);
    if (glm::length(v) < 1e-6) {
        const rc::Vec3 other = std::abs(n.x) < 0.9 ? rc::Vec3(1, 0, 0) : rc::Vec3(0, 1, 0);
        v = other - n * glm::dot(other, n);
    }
    return glm::normalize(v);
}

rc::Vec3 rotate(const rc::Vec3& v, const rc::Vec3& axis, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1 - c);
}

QString num(double v) { return QString::number(v, 'g', 3); }

}  // namespace

SceneSketch SceneSketch::of(const rc::SessionState& s, const rc::Selection& sel, bool samples) {
    SceneSketch k;
    const rc::Scene& scene = s.scene();
    for (int id = 0; id < scene.size(); ++id) {
        const rc::Object& o = scene.objects[std::size_t(id)];
        Body b{id, o.shape, o.bound, {}};
        if (o.shape == rc::Shape::Polygon) b.polygon = scene.polygons[std::size_t(o.index)].vertices;
        k.bodies.push_back(std::move(b));
    }
    for (const rc::Light& l : scene.lights) k.lights.push_back(l.position);
    k.eye = scene.camera.from;
    k.forward = glm::normalize(scene.camera.at - scene.camera.from);
    k.up = perpendicular(k.forward, scene.camera.up);
    k.bound = scene.bound;
    k.hasCylinder = s.session().options().cache != rc::CacheKind::Blocker;
    k.focus = rc::RayFocus::of(s, sel);
    if (!k.focus) return k;
    const rc::RayFocus& f = *k.focus;
    k.focusLabel = QString("%1 of pixel (%2,%3)")
                       .arg(QString::fromStdString(s.session().cacheTree().label(f.node)))
                       .arg(f.pixel % s.width())
                       .arg(f.pixel / s.width());
    // The pixel's ray tree: every committed ray, the one in focus marked
    const rc::TraceRecorder& rec = s.recorder();
    for (int i : rec.eventsOf(f.pixel)) {
        if (rec.events()[std::size_t(i)].deferred()) continue;
        if (auto r = rc::RayFocus::ofEvent(s, i))
            k.rays.push_back({r->ray.o, r->segmentEnd(scene), r->kind, i == f.event});
    }
    if (f.deferred) k.rays.push_back({f.ray.o, f.segmentEnd(scene), f.kind, true});
    if (samples) k.fan = s.fan(f.pixel);
    k.hull = rc::hullOf(s, f);
    k.cylinder = rc::cylinderOf(s, f);
    // The object that sets the cylinder's radius: nearest its axis, the ray's own excepted,
    // each measured by rc::safetyRadius alone (tutorial 02's function: in a student build,
    // the student's)
    const rc::SafetyCylinder& c = k.cylinder.cylinder;
    if (c.radius >= 0.0) {
        double best = rc::kNoHit;
        std::vector<rc::Sphere> one(1);
        for (int id = 0; id < scene.size(); ++id) {
            if (id == f.hit || id == f.origin.object) continue;
            one[0] = scene.objects[std::size_t(id)].bound;
            const double gap = rc::safetyRadius(one, -1, c.a, c.b);
            if (gap < best) {
                best = gap;
                k.limiter = id;
            }
        }
    }
    return k;
}

// [scene-basis]
SceneBasis SceneBasis::of(const SceneSketch& k, SceneAngle angle, double yaw, double pitch) {
    SceneBasis b;
    // The axis of what is in focus: from the hull's origin to its target, else the ray
    rc::Vec3 axis = k.forward;
    if (k.focus) axis = glm::normalize(k.focus->ray.d);
    if (k.hull.valid() && glm::length(k.hull.b.c - k.hull.a.c) > 1e-9) axis = glm::normalize(k.hull.b.c - k.hull.a.c);
    switch (angle) {
        case SceneAngle::Side:  // across the axis: it runs left to right, the camera's up is up
            b.x = axis;
            b.y = perpendicular(axis, k.up);
            b.z = glm::cross(b.x, b.y);
            break;
        case SceneAngle::Along: {  // down the ray in focus, from behind its origin
            const rc::Vec3 d = k.focus ? glm::normalize(k.focus->ray.d) : k.forward;
            b.z = -d;
            b.y = perpendicular(b.z, k.up);
            b.x = glm::cross(b.y, b.z);
            break;
        }
        case SceneAngle::Top:  // from above: the eye's view direction points up the screen
            b.z = k.up;
            b.y = perpendicular(b.z, k.forward);
            b.x = glm::cross(b.y, b.z);
            break;
        case SceneAngle::Front:  // from the eye's side, without perspective
            b.z = -k.forward;
            b.y = k.up;
            b.x = glm::cross(b.y, b.z);
            break;
    }
    // Orbit: yaw about the screen's up, then pitch about the screen's x
    const double ya = yaw * M_PI / 180.0, pa = pitch * M_PI / 180.0;
    b.x = rotate(b.x, b.y, ya);
    b.z = rotate(b.z, b.y, ya);
    b.y = rotate(b.y, b.x, pa);
    b.z = rotate(b.z, b.x, pa);
    return b;
}
// [scene-basis]

QPointF SceneBasis::project(const rc::Vec3& p) const { return {glm::dot(p, x), glm::dot(p, y)}; }
double SceneBasis::depth(const rc::Vec3& p) const { return glm::dot(p, z); }

QPolygonF discHull(const QPointF& a, double ra, const QPointF& b, double rb, int samples) {
    QPolygonF pts;
    for (int i = 0; i < samples; ++i) {
        const double t = 2.0 * M_PI * i / samples;
        const QPointF u(std::cos(t), std::sin(t));
        pts << a + ra * u << b + rb * u;
    }
    return convexHull(pts);
}

SceneView::SceneView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(200, 200);
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    angleBox_ = new QComboBox(this);
    angleBox_->addItem("side: across the ray (Figure 2)", int(SceneAngle::Side));
    angleBox_->addItem("along the ray (Figure 1)", int(SceneAngle::Along));
    angleBox_->addItem("top", int(SceneAngle::Top));
    angleBox_->addItem("front", int(SceneAngle::Front));
    angleBox_->setToolTip("How the scene is seen; drag to orbit, wheel to zoom, double-click to reset");
    wholeBox_ = new QCheckBox("whole scene", this);
    wholeBox_->setToolTip("Frame the whole scene, not the ray in focus");
    row->addStretch(1);
    row->addWidget(angleBox_);
    row->addWidget(wholeBox_);
    layout->addStretch(1);
    layout->addLayout(row);
    connect(angleBox_, &QComboBox::activated, this, [this](int i) { setAngle(SceneAngle(angleBox_->itemData(i).toInt())); });
    connect(wholeBox_, &QCheckBox::toggled, this, &SceneView::setWholeScene);
}

namespace {

/// What the bodies' layer shows of a sketch: each body, and which are drawn bold.
bool sameBodies(const SceneSketch& a, const SceneSketch& b) {
    auto bold = [](const SceneSketch& k) {
        std::vector<int> ids = k.hull.blockers;
        ids.insert(ids.end(), {k.hull.targetObject, k.limiter, k.focus ? k.focus->hit : -2,
                               k.focus ? k.focus->origin.object : -2});
        return ids;
    };
    auto same = [](const SceneSketch::Body& x, const SceneSketch::Body& y) {
        return x.id == y.id && x.shape == y.shape && x.bound.c == y.bound.c && x.bound.r == y.bound.r &&
               x.polygon == y.polygon;
    };
    return std::equal(a.bodies.begin(), a.bodies.end(), b.bodies.begin(), b.bodies.end(), same) &&
           a.hull.valid() == b.hull.valid() && bold(a) == bold(b);
}

}  // namespace

void SceneView::setSketch(SceneSketch sketch) {
    // The bodies' layer is drawn again only when what it shows has changed
    if (!sameBodies(sketch, sketch_)) ++sketchSerial_;
    sketch_ = std::move(sketch);
    update();
}

void SceneView::setAngle(SceneAngle a) {
    angle_ = a;
    yaw_ = pitch_ = 0.0;
    zoom_ = 1.0;
    angleBox_->setCurrentIndex(angleBox_->findData(int(a)));
    update();
}

void SceneView::setLayers(bool cylinder, bool hull, bool samples) {
    cylinderShown_ = cylinder;
    hullShown_ = hull;
    samplesShown_ = samples;
    update();
}

void SceneView::setOrbit(double yaw, double pitch) {
    yaw_ = yaw;
    pitch_ = std::clamp(pitch, -90.0, 90.0);
    update();
}

void SceneView::setWholeScene(bool on) {
    whole_ = on;
    if (wholeBox_->isChecked() != on) wholeBox_->setChecked(on);
    zoom_ = 1.0;
    update();
}

QPolygonF SceneView::studentHull(const rc::Sphere& a, const rc::Sphere& b) const {
    const rc::Hull h(a, b);
    rc::Vec3 m = (a.c + b.c) * 0.5;
    if (h.distance(m) > 0.0) m = a.r >= b.r ? a.c : b.c;
    const double reach = 2.0 * (glm::length(b.c - a.c) + a.r + b.r) + 1.0;
    QPolygonF out;
    const int n = 256;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * M_PI * i / n;
        const rc::Vec3 u = std::cos(t) * basis_.x + std::sin(t) * basis_.y;
        if (h.distance(m + reach * u) <= 0.0) continue;
        double lo = 0.0, hi = reach;
        for (int k = 0; k < 48; ++k) (h.distance(m + 0.5 * (lo + hi) * u) <= 0.0 ? lo : hi) = 0.5 * (lo + hi);
        out << toWidget(m + lo * u);
    }
    return out;
}

QPointF SceneView::toWidget(const rc::Vec3& p) const {
    const QPointF q = basis_.project(p);
    return QPointF(width() / 2.0 + (q.x() - centre_.x()) * scale_, height() / 2.0 - (q.y() - centre_.y()) * scale_);
}

void SceneView::frame() {
    basis_ = SceneBasis::of(sketch_, angle_, yaw_, pitch_);
    // What must be seen: the ray in focus with its hull, cylinder and blockers; else the scene
    QRectF box;
    auto add = [&](const rc::Vec3& c, double r) {
        const QPointF q = basis_.project(c);
        const QRectF b(q.x() - r, q.y() - r, 2 * r, 2 * r);
        box = box.isNull() ? b : box.united(b);
    };
    const SceneSketch& k = sketch_;
    if (!whole_ && k.focus) {
        if (k.hull.valid()) {
            add(k.hull.a.c, k.hull.a.r);
            add(k.hull.b.c, k.hull.b.r);
            for (int id : k.hull.blockers) add(k.bodies[std::size_t(id)].bound.c, k.bodies[std::size_t(id)].bound.r);
        }
        if (k.cylinder.cylinder.radius > 0.0) {
            add(k.cylinder.cylinder.a, k.cylinder.cylinder.radius);
            add(k.cylinder.cylinder.b, k.cylinder.cylinder.radius);
        }
        if (k.focus->hit >= 0 && k.focus->hit < int(k.bodies.size()))
            add(k.bodies[std::size_t(k.focus->hit)].bound.c, k.bodies[std::size_t(k.focus->hit)].bound.r);
        if (cylinderShown_ && k.limiter >= 0 && k.cylinder.cylinder.radius > 0.0)
            add(k.bodies[std::size_t(k.limiter)].bound.c, k.bodies[std::size_t(k.limiter)].bound.r);
        // The sample rays' hits and the lights' spheres they fan to
        if (samplesShown_ && !k.fan.rays.empty()) {
            for (const rc::FanRay& r : k.fan.rays)
                if (r.kind != rc::RayKind::Primary && r.outcome != rc::FanOutcome::Missed) add(r.to, 0.0);
            for (const rc::Sphere& l : k.fan.lights)
                if (l.r > 0.0) add(l.c, l.r);
        }
        if (angle_ != SceneAngle::Along) {
            for (const auto& s : k.rays)
                if (s.focus) {
                    add(s.a, 0.0);
                    add(s.b, 0.0);
                }
        } else {
            add(k.focus->ray.o, 0.0);
        }
    }
    if (box.isNull() || box.width() + box.height() <= 0.0) {
        add(k.bound.c, k.bound.r);
        add(k.eye, 0.0);
    }
    const double margin = 0.12 * std::max(box.width(), box.height()) + 1e-9;
    box.adjust(-margin, -margin, margin, margin);
    // Room for the caption above (drawn first) and the angle box below
    const double top = drawingRect().top() + 8, bottom = angleBox_->sizeHint().height() + 16;
    const double w = std::max(1.0, width() - 16.0), h = std::max(1.0, height() - top - bottom);
    scale_ = zoom_ * std::min(w / box.width(), h / box.height());
    centre_ = box.center();
    // Shift so the drawing sits between the caption and the angle box
    centre_.ry() += (top - bottom) / 2.0 / scale_;
}

void SceneView::paintBodies(QPainter& p, const std::vector<bool>& blocker, int target, double lw) const {
    const SceneSketch& k = sketch_;
    auto disc = [&](const rc::Sphere& s) {
        const QPointF c = toWidget(s.c);
        const double r = std::max(1.0, s.r * scale_);
        return QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r);
    };
    const QRectF screen = QRectF(rect()).adjusted(-4, -4, 4, 4);
    std::vector<int> order;
    order.reserve(k.bodies.size());
    for (std::size_t i = 0; i < k.bodies.size(); ++i)
        if (disc(k.bodies[i].bound).intersects(screen)) order.push_back(int(i));
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return basis_.depth(k.bodies[std::size_t(a)].bound.c) < basis_.depth(k.bodies[std::size_t(b)].bound.c);
    });
    for (int id : order) {
        const SceneSketch::Body& b = k.bodies[std::size_t(id)];
        const bool bold = blocker[std::size_t(id)] || id == target || (cylinderShown_ && id == k.limiter) ||
                          (k.focus && (id == k.focus->hit || id == k.focus->origin.object));
        const QColor line = bold ? QColor(235, 235, 235) : QColor(150, 150, 160);
        if (b.shape == rc::Shape::Polygon) {
            QPolygonF poly;
            for (const rc::Vec3& v : b.polygon) poly << toWidget(v);
            if (const QRectF box = poly.boundingRect(); !bold && std::max(box.width(), box.height()) < 4.0 * lw) {
                p.fillRect(box, line);  // a few pixels across: a dot, as for small discs below
                continue;
            }
            p.setPen(pen(line, (bold ? 2.5 : 1.0) * lw));
            p.setBrush(QColor(90, 90, 100, 90));
            p.drawPolygon(poly);
        } else if (const QRectF d = disc(b.bound); !bold && d.width() < 4.0 * lw) {
            // A body a few pixels across: a dot in its outline's colour (thousands of
            // antialiased outlines that small would only cost time)
            p.fillRect(d, line);
        } else {
            p.setPen(pen(line, (bold ? 3.0 : 1.2) * lw, b.shape == rc::Shape::Cone ? Qt::DashLine : Qt::SolidLine));
            p.setBrush(QColor(70, 72, 84, 200));
            p.drawEllipse(d);
        }
    }
}

QRectF SceneView::discOf(const rc::Sphere& s) const {
    const QPointF c = toWidget(s.c);
    const double r = std::max(1.0, s.r * scale_);
    return QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r);
}

QPolygonF SceneView::hullOf(const rc::Sphere& a, const rc::Sphere& b) const {
    // A student build with tutorial 03 open draws the student's own rc::Hull: its section
    // in the view's plane through the hull's axis, found by bisection on Hull::distance()
    // along rays from a point inside it (a wrong hull shows as the shape it is)
    if (rc::isStudents(3)) return studentHull(a, b);
    return discHull(toWidget(a.c), a.r * scale_, toWidget(b.c), b.r * scale_);
}

void SceneView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(28, 30, 36));
    p.setRenderHint(QPainter::Antialiasing, true);
    // Text in pixels, as the image view's legend: alike on any screen and in a screenshot
    p.setFont(legendFont(font()));
    // The caption first: the drawing goes under it, never beneath it
    const bool fan = samplesShown_ && !sketch_.fan.rays.empty();
    const QStringList cap = captionLines(fan);
    caption_ = cap.join("\n");
    const QFontMetricsF fm(legendFont(font()));
    // Lines wider than the view wrap: the caption keeps the font of the rest (large on a
    // projector), never cut off
    double cw = 0;
    for (const QString& c : cap) cw = std::max(cw, fm.horizontalAdvance(c));
    cw = std::min(cw, std::max(40.0, width() - 32.0));
    const auto lineHeight = [&](const QString& c) {
        return fm.boundingRect(QRectF(0, 0, cw + 2, 1e6), Qt::TextWordWrap, c).height();
    };
    double total = 0;
    for (const QString& c : cap) total += lineHeight(c);
    captionRect_ = QRectF(8, 8, cw + 16, total + 8);
    // Frame the sketch below the caption; project spheres and hulls to the widget
    frame();
    const double lw = std::max(1.0, fm.height() / 9.0);  // lines follow Large fonts
    p.save();
    p.setClipRect(drawingRect());
    paintBodiesLayer(p, lw);
    paintFocusShapes(p, lw);
    paintFan(p, lw);
    paintRays(p, fan, lw);
    p.restore();
    paintLabels(p, lw);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 175));
    p.drawRoundedRect(captionRect_, 6, 6);
    p.setPen(Qt::white);
    double y = 12;
    for (const QString& c : cap) {
        const double h = lineHeight(c);
        p.drawText(QRectF(16, y, cw + 2, h), Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap, c);
        y += h;
    }
}

QRectF SceneView::drawingRect() const {
    const double top = captionRect_.isNull() ? 0.0 : captionRect_.bottom() + 4;
    return QRectF(0, top, width(), std::max(0.0, height() - top));
}

void SceneView::paintBodiesLayer(QPainter& p, double lw) {
    const SceneSketch& k = sketch_;
    // Which objects the overlays mark: the potential blockers and the target
    std::vector<bool> blocker(k.bodies.size(), false);
    for (int id : k.hull.blockers) blocker[std::size_t(id)] = true;
    const int target = k.hull.valid() ? k.hull.targetObject : (k.focus ? k.focus->hit : -1);

    // [scene-view-paint]
    // The objects, farthest first, so that nearer ones are drawn over them: only those on
    // screen, drawn once into a layer kept while the sketch and the view stay the same
    // (a scene of thousands of spheres costs one image a repaint)
    const QPointF p0 = toWidget(rc::Vec3(0.0)), px = toWidget(rc::Vec3(1, 0, 0)), py = toWidget(rc::Vec3(0, 1, 0)),
                  pz = toWidget(rc::Vec3(0, 0, 1));
    const std::vector<double> layerKey{double(sketchSerial_), double(width()), double(height()), devicePixelRatioF(),
                                       p0.x(), p0.y(), px.x(), px.y(), py.x(), py.y(), pz.x(), pz.y(), lw,
                                       double(cylinderShown_)};
    if (layerKey != bodiesKey_) {
        bodiesKey_ = layerKey;
        bodies_ = QPixmap(size() * devicePixelRatioF());
        bodies_.setDevicePixelRatio(devicePixelRatioF());
        bodies_.fill(Qt::transparent);
        QPainter lp(&bodies_);
        lp.setRenderHint(QPainter::Antialiasing, true);
        paintBodies(lp, blocker, target, lw);
    }
    p.drawPixmap(0, 0, bodies_);

}

void SceneView::paintFocusShapes(QPainter& p, double lw) const {
    const SceneSketch& k = sketch_;
    // The blocker hull of origin and target, its potential blockers, origin and target
    if (k.hull.valid() && hullShown_) {
        p.setPen(pen(palette::kHull, 2.5 * lw));
        p.setBrush(withAlpha(palette::kHull, 45));
        p.drawPolygon(hullOf(k.hull.a, k.hull.b));
        p.setBrush(Qt::NoBrush);
        p.setPen(pen(palette::kOrigin, 2.0 * lw, Qt::DashLine));
        if (k.hull.a.r > 0) p.drawEllipse(discOf(k.hull.a));
        p.setPen(pen(palette::kTarget, 3.0 * lw));
        p.setBrush(withAlpha(palette::kTarget, 50));
        if (k.hull.b.r > 0) p.drawEllipse(discOf(k.hull.b));
        p.setPen(pen(palette::kBlocker, 3.0 * lw));
        p.setBrush(withAlpha(palette::kBlocker, 110));
        for (int id : k.hull.blockers) p.drawEllipse(discOf(k.bodies[std::size_t(id)].bound));
    }
    // The cylinder of safety: a capsule, so its outline is the hull of its end discs
    const rc::SafetyCylinder& cyl = k.cylinder.cylinder;
    if (k.focus && cyl.radius > 0.0 && cylinderShown_) {
        p.setPen(pen(palette::kCylinder, 2.5 * lw, k.cylinder.cached ? Qt::SolidLine : Qt::DashLine));
        p.setBrush(withAlpha(palette::kCylinder, 60));
        p.drawPolygon(discHull(toWidget(cyl.a), cyl.radius * scale_, toWidget(cyl.b), cyl.radius * scale_));
    }
}

void SceneView::paintFan(QPainter& p, double lw) const {
    const SceneSketch& k = sketch_;
    // The sample rays of the pixel in focus: the shadow rays fan out to the light's sphere
    const bool fan = samplesShown_ && !k.fan.rays.empty();
    if (fan) {
        // Solid pens (a dash pattern costs a stroke per dash); a large fan in hairlines and
        // without halos, as in the image view: wide pens are filled as paths, slow for thousands
        const bool hairlines = int(k.fan.rays.size()) > rc::SampleFan::kHaloRays;
        if (!hairlines)
            for (const rc::FanRay& r : k.fan.rays) {
                p.setPen(pen(QColor(0, 0, 0, 150), 3.0 * lw));
                p.drawLine(toWidget(r.from), toWidget(r.to));
            }
        for (const rc::FanRay& r : k.fan.rays) {
            p.setPen(pen(palette::fanOutcome(r.outcome), hairlines ? 1.0 : 1.3 * lw));
            p.drawLine(toWidget(r.from), toWidget(r.to));
            if (r.outcome == rc::FanOutcome::Blocked) {
                p.setPen(pen(withAlpha(palette::kShadowBlocked, 90), 1.0));
                p.drawLine(toWidget(r.to), toWidget(r.aim));
            }
        }
    }
    // The lights' spheres over the rays' ends: every shadow ray ends inside one
    for (const rc::Sphere& l : k.fan.lights) {
        if (!fan || !(l.r > 0.0)) continue;
        p.setPen(pen(palette::kLight, 2.0 * lw));
        p.setBrush(withAlpha(palette::kLight, 60));
        p.drawEllipse(discOf(l));
    }
}

void SceneView::paintRays(QPainter& p, bool fan, double lw) const {
    const SceneSketch& k = sketch_;
    // The ray tree of the pixel in focus (the fan holds its rays: only the focus then); the
    // ray in focus thick, with its direction
    for (const auto& s : k.rays) {
        if (fan && !s.focus) continue;
        const QColor c = s.kind == rc::RayKind::Shadow ? QColor(255, 245, 157) : palette::kRay;
        p.setPen(pen(QColor(0, 0, 0, 170), (s.focus ? 4.5 : 2.5) * lw));
        p.drawLine(toWidget(s.a), toWidget(s.b));
        p.setPen(pen(c, (s.focus ? 3.0 : 1.2) * lw, s.kind == rc::RayKind::Shadow ? Qt::DashLine : Qt::SolidLine));
        p.drawLine(toWidget(s.a), toWidget(s.b));
    }
    // Lights (stars) and the eye
    for (const rc::Vec3& l : k.lights) {
        const QPointF c = toWidget(l);
        // Small over a light's sphere, so the rays' ends in it show
        const double arm = fan && !k.fan.lights.empty() && k.fan.lights.front().r > 0.0 ? 3.0 : 7.0;
        p.setPen(pen(palette::kLight, 2.0 * lw));
        for (int a = 0; a < 4; ++a) {
            const double t = a * M_PI / 4;
            const QPointF d(std::cos(t) * arm * lw, std::sin(t) * arm * lw);
            p.drawLine(c - d, c + d);
        }
    }
    const QPointF eye = toWidget(k.eye);
    p.setPen(pen(Qt::white, 2.0 * lw));
    p.setBrush(QColor(40, 40, 40));
    p.drawEllipse(eye, 5 * lw, 5 * lw);
    // The ray's axis after the eye, so that an eye ray seen end-on shows over the eye's mark
    if (k.focus) {
        // The ray's axis: a + where it starts (seen end-on in the view along the ray)
        const QPointF o = toWidget(k.focus->ray.o);
        const double m = 7.0 * lw;
        p.setPen(pen(palette::kRay, 2.5 * lw));
        p.drawLine(o - QPointF(m, 0), o + QPointF(m, 0));
        p.drawLine(o - QPointF(0, m), o + QPointF(0, m));
        const QPointF tip = toWidget(k.focus->ray.o + k.focus->ray.d * (40.0 * lw / scale_));
        const QLineF dir(o, tip);
        if (dir.length() > 8 * lw) {
            const QLineF back = QLineF(tip, o).unitVector();
            const QPointF u = (back.p2() - back.p1()) * (9.0 * lw);
            const QPointF n(-u.y() * 0.5, u.x() * 0.5);
            p.setBrush(palette::kRay);
            p.setPen(pen(Qt::black, 1.0));
            p.drawPolygon(QPolygonF({tip, tip + u + n, tip + u - n}));
        }
    }
    // [scene-view-paint]
}

QStringList SceneView::captionLines(bool fan) const {
    const SceneSketch& k = sketch_;
    const rc::SafetyCylinder& cyl = k.cylinder.cylinder;
    // Caption: what is seen, with the sizes the paper's figures compare
    QStringList cap;
    const QString angleName = angle_ == SceneAngle::Side    ? "Side view, across the ray"
                              : angle_ == SceneAngle::Along ? "View along the ray (+)"
                              : angle_ == SceneAngle::Top   ? "Top view"
                                                            : "Front view (no perspective)";
    cap << (k.focus ? angleName + ": " + k.focusLabel : angleName + ": no ray in focus");
    if (k.hull.valid() && hullShown_) {
        // The nearest few by number; the rest counted
        constexpr std::size_t kNamed = 8;
        QStringList ids;
        for (std::size_t i = 0; i < std::min(kNamed, k.hull.blockers.size()); ++i) {
            const int id = k.hull.blockers[i];
            ids << QString("#%1%2").arg(id).arg(k.focus && id == k.focus->origin.object ? " (the origin)" : "");
        }
        if (k.hull.listed > std::size_t(ids.size())) ids << QString("and %L1 more").arg(k.hull.listed - std::size_t(ids.size()));
        cap << QString("blocker hull of origin (r %1) and target (r %2): %L3 potential blocker%4%5")
                   .arg(num(k.hull.a.r), num(k.hull.b.r)).arg(k.hull.listed)
                   .arg(k.hull.listed == 1 ? "" : "s").arg(ids.isEmpty() ? "" : ": " + ids.join(", "));
    }
    if (k.focus && cyl.radius > 0.0 && cylinderShown_) {
        cap << QString("cylinder of safety%1: radius %2").arg(k.cylinder.cached ? "" : " (around this ray)", num(cyl.radius));
        QString c;
        const int hit = k.focus->hit;
        if (hit >= 0 && hit < int(k.bodies.size()))
            c = QString("%1% of the radius of the %2 hit, #%3 (%4)")
                    .arg(num(100.0 * cyl.radius / k.bodies[std::size_t(hit)].bound.r))
                    .arg(boundName(k.bodies[std::size_t(hit)].shape)).arg(hit)
                    .arg(num(k.bodies[std::size_t(hit)].bound.r));
        if (k.limiter >= 0) c += QString("%1#%2 sets it").arg(c.isEmpty() ? "" : "; ").arg(k.limiter);
        if (!c.isEmpty()) cap << c;
    }
    if (fan) {
        const int eye = k.fan.count(rc::RayKind::Primary), shadow = k.fan.count(rc::RayKind::Shadow);
        cap << QString("samples: %1 eye, %2 reflected or refracted, %3 shadow: %4 reach the light, %5 blocked%6")
                   .arg(eye).arg(int(k.fan.rays.size()) - eye - shadow).arg(shadow)
                   .arg(k.fan.count(rc::FanOutcome::Lit)).arg(k.fan.count(rc::FanOutcome::Blocked))
                   .arg(k.fan.cut ? QString(", the first %1").arg(k.fan.rays.size()) : QString());
    }
    return cap;
}

void SceneView::paintLabels(QPainter& p, double lw) {
    const SceneSketch& k = sketch_;
    const rc::SafetyCylinder& cyl = k.cylinder.cylinder;
    const QFontMetricsF fm(legendFont(font()));
    labelRects_.clear();
    const auto label = [&](const QPointF& at, const QString& t, const QColor& c) { placeLabel(p, at, t, c); };
    label(toWidget(k.eye), "eye", Qt::white);
    // The paper's Figure 1: the ray, its cylinder of safety and the sphere it hits, named
    if (k.focus && cylinderShown_) {
        const int hit = k.focus->hit;
        if (hit >= 0 && hit < int(k.bodies.size())) {
            const SceneSketch::Body& body = k.bodies[std::size_t(hit)];
            const rc::Sphere& b = body.bound;
            label(toWidget(b.c) + QPointF(b.r * scale_ * 0.6, -b.r * scale_ * 0.6),
                  QString("%1 hit #%2").arg(shapeName(body.shape)).arg(hit), palette::kTarget);
        }
        if (cyl.radius > 0.0)
            label(toWidget(cyl.a) + QPointF(cyl.radius * scale_, cyl.radius * scale_ * 0.5), "cylinder of safety",
                  palette::kCylinder);
        label(toWidget(k.focus->ray.o) + QPointF(8 * lw, 8 * lw + fm.height()), "ray", palette::kRay);
    }
    for (std::size_t i = 0; i < k.lights.size(); ++i) label(toWidget(k.lights[i]), QString("light %1").arg(i + 1), palette::kLight);
    if (k.hull.valid() && hullShown_) {
        const rc::Sphere& a = k.hull.a;
        label(toWidget(a.c) + QPointF(0, a.r * scale_ * 0.7), "origin", palette::kOrigin);
        label(toWidget(k.hull.b.c) + QPointF(k.hull.b.r * scale_ * 0.5, -k.hull.b.r * scale_ * 0.7),
              k.hull.targetObject >= 0 ? QString("target #%1").arg(k.hull.targetObject) : QString("target"), palette::kTarget);
        for (int id : k.hull.blockers) {
            if (id == k.hull.targetObject || (k.focus && id == k.focus->origin.object)) continue;  // labelled already
            const rc::Sphere& b = k.bodies[std::size_t(id)].bound;
            label(toWidget(b.c) + QPointF(b.r * scale_ * 0.7, b.r * scale_), QString("blocker #%1").arg(id), palette::kBlocker);
        }
    }
}

void SceneView::placeLabel(QPainter& p, const QPointF& at, const QString& t, const QColor& c) {
    // Each label in the view, clear of the caption and of the labels before it (moved a
    // line down or up at a time until it is), so that none hides another
    const QFontMetricsF fm(legendFont(font()));
    const QRectF& box = captionRect_;
    QRectF r(at.x() + 6, at.y() - fm.height() - 2, fm.horizontalAdvance(t) + 8, fm.height() + 2);
    if (r.right() > width() - 4) r.moveRight(width() - 4);  // stays in the view
    if (r.left() < 4) r.moveLeft(4);
    // Above the view's own controls (the angle and whole-scene boxes at its foot)
    const double floor = std::min({double(height()), double(angleBox_->geometry().top()), double(wholeBox_->geometry().top())}) - 4;
    auto inView = [&](QRectF q) {
        if (q.bottom() > floor) q.moveBottom(floor);
        if (q.top() < 4) q.moveTop(4);
        return q;
    };
    auto clashes = [&](const QRectF& q) {
        if (q.intersects(box) || q.bottom() > floor) return true;
        for (const QRectF& o : labelRects_)
            if (o.intersects(q)) return true;
        return false;
    };
    const double line = r.height() + 3;
    QRectF at0 = inView(r);
    for (int i = 0; i < 40 && clashes(at0); ++i) at0 = inView(r.translated(0, (i % 2 == 0 ? 1 : -1) * (i / 2 + 1) * line));
    if (clashes(at0)) return;  // no room left: the caption names what it would have
    r = at0;
    labelRects_.push_back(r);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 150));
    p.drawRoundedRect(r, 3, 3);
    p.setPen(c);
    p.drawText(r, Qt::AlignCenter, t);
}

void SceneView::mousePressEvent(QMouseEvent* e) { lastPos_ = e->position(); }

void SceneView::mouseMoveEvent(QMouseEvent* e) {
    if (!(e->buttons() & Qt::LeftButton)) return;
    const QPointF d = e->position() - lastPos_;
    lastPos_ = e->position();
    setOrbit(yaw_ + d.x() * 0.5, pitch_ + d.y() * 0.5);
}

void SceneView::mouseDoubleClickEvent(QMouseEvent*) {
    yaw_ = pitch_ = 0.0;
    zoom_ = 1.0;
    update();
}

void SceneView::wheelEvent(QWheelEvent* e) {
    zoom_ = std::clamp(zoom_ * std::pow(1.25, e->angleDelta().y() / 120.0), 0.05, 500.0);
    update();
    e->accept();
}

}  // namespace rcgui
