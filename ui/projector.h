#pragma once
/// \file
/// \brief The overlays' projector in Qt's types: rc::ImageProjector (the Qt-free core's)
/// with its outlines as QPolygonF, its points as QPointF and its segments as QLineF.
#include <optional>

#include <QLineF>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>

#include "view/image_projector.h"

namespace rcgui {

/// rc::ImageProjector, for QPainter: see there for what each outline is.
class Projector {
public:
    Projector(const rc::Camera& camera, const rc::RayGenerator& rays) : core_(camera, rays) {}
    void setClip(const QRectF& clip);
    QRectF clip() const;
    bool covers(const QPolygonF& poly) const;
    std::optional<QPointF> point(const rc::Vec3& p) const;
    std::optional<QLineF> segment(const rc::Vec3& p, const rc::Vec3& q) const;
    QPolygonF silhouette(const rc::Sphere& s, int samples = 64) const;
    QPolygonF hull(rc::Sphere a, rc::Sphere b, int samples = 64) const;
    QPolygonF eyeCone(const rc::Vec3& axis, double angle, int samples = 64) const;
    QPolygonF polygon(const rc::Polygon& p) const;
    double depth(const rc::Vec3& p) const { return core_.depth(p); }
    const rc::Vec3& eye() const { return core_.eye(); }
    double nearPlane() const { return core_.nearPlane(); }
    const rc::ImageProjector& core() const { return core_; }

private:
    rc::ImageProjector core_;
};

/// The core's outlines and rectangles in Qt's types, and back.
QPolygonF toQt(const rc::Outline& outline);
rc::Outline fromQt(const QPolygonF& poly);
rc::ImageRect fromQt(const QRectF& rect);

/// rc::clipConvex, rc::clipLine and rc::convexHull in Qt's types.
QPolygonF clipConvex(const QPolygonF& poly, const QRectF& rect);
std::optional<QLineF> clipLine(const QLineF& line, const QRectF& rect);
QPolygonF convexHull(const QPolygonF& points);

}  // namespace rcgui
