#include "projector.h"

namespace rcgui {

QPolygonF toQt(const rc::Outline& outline) {
    QPolygonF out;
    out.reserve(qsizetype(outline.size()));
    for (const rc::ImagePoint& p : outline) out << QPointF(p.x, p.y);
    return out;
}

rc::Outline fromQt(const QPolygonF& poly) {
    rc::Outline out;
    out.reserve(std::size_t(poly.size()));
    for (const QPointF& p : poly) out.emplace_back(p.x(), p.y());
    return out;
}

rc::ImageRect fromQt(const QRectF& rect) {
    if (rect.isNull()) return {};
    const QRectF r = rect.normalized();
    return {r.left(), r.top(), r.right(), r.bottom()};
}

void Projector::setClip(const QRectF& clip) { core_.setClip(fromQt(clip)); }

QRectF Projector::clip() const {
    const rc::ImageRect& c = core_.clip();
    return c.empty() ? QRectF() : QRectF(QPointF(c.left, c.top), QPointF(c.right, c.bottom));
}

bool Projector::covers(const QPolygonF& poly) const { return core_.covers(fromQt(poly)); }

std::optional<QPointF> Projector::point(const rc::Vec3& p) const {
    if (const auto q = core_.point(p)) return QPointF(q->x, q->y);
    return std::nullopt;
}

std::optional<QLineF> Projector::segment(const rc::Vec3& p, const rc::Vec3& q) const {
    if (const auto l = core_.segment(p, q)) return QLineF(l->a.x, l->a.y, l->b.x, l->b.y);
    return std::nullopt;
}

QPolygonF Projector::silhouette(const rc::Sphere& s, int samples) const { return toQt(core_.silhouette(s, samples)); }
QPolygonF Projector::hull(rc::Sphere a, rc::Sphere b, int samples) const { return toQt(core_.hull(a, b, samples)); }
QPolygonF Projector::eyeCone(const rc::Vec3& axis, double angle, int samples) const {
    return toQt(core_.eyeCone(axis, angle, samples));
}
QPolygonF Projector::polygon(const rc::Polygon& p) const { return toQt(core_.polygon(p)); }

QPolygonF clipConvex(const QPolygonF& poly, const QRectF& rect) { return toQt(rc::clipConvex(fromQt(poly), fromQt(rect))); }

std::optional<QLineF> clipLine(const QLineF& line, const QRectF& rect) {
    if (const auto l = rc::clipLine({{line.x1(), line.y1()}, {line.x2(), line.y2()}}, fromQt(rect)))
        return QLineF(l->a.x, l->a.y, l->b.x, l->b.y);
    return std::nullopt;
}

QPolygonF convexHull(const QPolygonF& points) { return toQt(rc::convexHull(fromQt(points))); }

}  // namespace rcgui
