#pragma once
/// \file
/// \brief Projects world geometry (points, spheres, capsules, sphere hulls) into image
/// coordinates through the render's camera, for the overlays.
#include <optional>

#include <QLineF>
#include <QPointF>
#include <QPolygonF>

#include "geometry/polygon.h"
#include "geometry/sphere.h"
#include "scene/camera.h"

namespace rcgui {

/// Image coordinates put pixel (x, y) in the unit square [x, x+1) x [y, y+1): the eye
/// ray of a pixel goes through its centre, (x + 0.5, y + 0.5).
class Projector {
public:
    Projector(const rc::Camera& camera, const rc::RayGenerator& rays);

    /// The image position of a world point, or nothing when it is behind the eye.
    std::optional<QPointF> point(const rc::Vec3& p) const;
    /// The projected segment p-q, clipped to the half-space in front of the eye.
    std::optional<QLineF> segment(const rc::Vec3& p, const rc::Vec3& q) const;
    /// The outline of a sphere as seen from the eye (its tangent circle, projected);
    /// empty when the eye is inside it or it is entirely behind the eye.
    QPolygonF silhouette(const rc::Sphere& s, int samples = 64) const;
    /// The outline of the convex hull of two spheres (both silhouettes and their tangent
    /// lines): the convex hull of the two projected silhouettes. A sphere holding the eye
    /// adds nothing: from inside, the hull is seen through the other sphere.
    QPolygonF hull(rc::Sphere a, rc::Sphere b, int samples = 64) const;
    /// The outline of the cone of eye rays within `angle` (radians) of direction `axis`.
    QPolygonF eyeCone(const rc::Vec3& axis, double angle, int samples = 64) const;
    /// The outline of a convex polygon.
    QPolygonF polygon(const rc::Polygon& p) const;
    /// Distance from the eye along the view direction.
    double depth(const rc::Vec3& p) const;
    const rc::Vec3& eye() const { return eye_; }

private:
    const rc::RayGenerator& rays_;
    rc::Vec3 eye_, forward_;
    double near_;
};

/// The convex hull of a point set (Andrew's monotone chain), counter-clockwise.
QPolygonF convexHull(QPolygonF points);

}  // namespace rcgui
