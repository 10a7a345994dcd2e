#pragma once
/// \file
/// \brief Projects world geometry (points, spheres, capsules, sphere hulls) into image
/// coordinates through the render's camera, for the overlays.
#include <optional>
#include <vector>

#include <QLineF>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>

#include "geometry/polygon.h"
#include "geometry/sphere.h"
#include "scene/camera.h"

namespace rcgui {

/// Image coordinates put pixel (x, y) in the unit square [x, x+1) x [y, y+1): the eye
/// ray of a pixel goes through its centre, (x + 0.5, y + 0.5).
///
/// Shapes are clipped in 3D against the near plane before they are projected (a part
/// behind it has no image), and then against the clip rectangle (the visible part of the
/// view, with a margin): what comes out is bounded by the view, however close to the
/// eye's plane a shape reaches. A shape holding the whole view comes back as the clip
/// rectangle itself (see covers()).
class Projector {
public:
    Projector(const rc::Camera& camera, const rc::RayGenerator& rays);
    /// Sets the rectangle (image coordinates) that outlines are clipped to. Without one,
    /// outlines are only clipped to the near plane and may be arbitrarily large.
    void setClip(const QRectF& clip) { clip_ = clip; }
    const QRectF& clip() const { return clip_; }
    /// True when `poly` (as returned here) holds the whole clip rectangle.
    bool covers(const QPolygonF& poly) const;

    /// The image position of a world point, or nothing when it is behind the eye.
    std::optional<QPointF> point(const rc::Vec3& p) const;
    /// The projected segment p-q, clipped to the half-space in front of the eye.
    std::optional<QLineF> segment(const rc::Vec3& p, const rc::Vec3& q) const;
    /// The outline of a sphere as seen from the eye (its tangent circle, projected, or
    /// the part of the sphere in front of the near plane); empty when the eye is inside it
    /// or it is entirely behind the near plane.
    QPolygonF silhouette(const rc::Sphere& s, int samples = 64) const;
    /// The outline of the convex hull of two spheres (both silhouettes and their tangent
    /// lines), clipped to the near plane. A sphere holding the eye adds nothing: from
    /// inside, the hull is seen through the other sphere. When the eye lies in the hull
    /// between the two, the hull holds the whole view.
    QPolygonF hull(rc::Sphere a, rc::Sphere b, int samples = 64) const;
    /// The outline of the cone of eye rays within `angle` (radians) of direction `axis`.
    QPolygonF eyeCone(const rc::Vec3& axis, double angle, int samples = 64) const;
    /// The outline of a convex polygon.
    QPolygonF polygon(const rc::Polygon& p) const;
    /// Distance from the eye along the view direction.
    double depth(const rc::Vec3& p) const;
    const rc::Vec3& eye() const { return eye_; }

    double nearPlane() const { return near_; }

private:
    /// Image position of a point at depth >= near_ (no checks).
    QPointF image(const rc::Vec3& p) const;
    /// Adds the outline points of the part of sphere `s` in front of the near plane.
    void sphereOutline(const rc::Sphere& s, int samples, QPolygonF& out) const;
    /// The clip rectangle as a polygon (or an empty one without a clip).
    QPolygonF whole() const;
    QPolygonF clipped(const QPolygonF& convex) const;

    const rc::RayGenerator& rays_;
    rc::Vec3 eye_, forward_;
    double near_;
    QRectF clip_;
};

/// Clips a convex polygon to a rectangle (Sutherland-Hodgman); the result is convex.
QPolygonF clipConvex(const QPolygonF& poly, const QRectF& rect);
/// Clips a segment to a rectangle (Liang-Barsky); nothing when it misses it.
std::optional<QLineF> clipLine(const QLineF& line, const QRectF& rect);

/// The convex hull of a point set (Andrew's monotone chain), counter-clockwise.
QPolygonF convexHull(QPolygonF points);

}  // namespace rcgui
