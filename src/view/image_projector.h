#pragma once
/// \file
/// \brief Projects world geometry (points, spheres, capsules, sphere hulls, cones,
/// polygons) into image coordinates through the render's camera: the outlines every
/// viewer of a render draws, whatever draws them (the Qt window, a browser).
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "geometry/polygon.h"
#include "geometry/sphere.h"
#include "scene/camera.h"

namespace rc {

/// A point of the image plane: pixel (x, y) covers [x, x+1) x [y, y+1).
using ImagePoint = glm::dvec2;
/// A closed outline (its last point joins its first); convex where the functions say so.
using Outline = std::vector<ImagePoint>;

/// A rectangle of the image plane (empty: no rectangle).
struct ImageRect {
    double left = 0, top = 0, right = 0, bottom = 0;
    bool empty() const { return !(right > left) || !(bottom > top); }
    double width() const { return right - left; }
    double height() const { return bottom - top; }
};

/// A segment of the image plane.
struct ImageSegment {
    ImagePoint a, b;
};

/// Image coordinates put pixel (x, y) in the unit square [x, x+1) x [y, y+1): the eye
/// ray of a pixel goes through its centre, (x + 0.5, y + 0.5).
///
/// Shapes are clipped in 3D against the near plane before they are projected (a part
/// behind it has no image), and then against the clip rectangle (the visible part of the
/// view, with a margin): what comes out is bounded by the view, however close to the
/// eye's plane a shape reaches. A shape holding the whole view comes back as the clip
/// rectangle itself (see covers()).
class ImageProjector {
public:
    ImageProjector(const Camera& camera, const RayGenerator& rays);
    /// Sets the rectangle that outlines are clipped to. Without one, outlines are only
    /// clipped to the near plane and may be arbitrarily large.
    void setClip(const ImageRect& clip) { clip_ = clip; }
    const ImageRect& clip() const { return clip_; }
    /// True when `outline` (as returned here) holds the whole clip rectangle.
    bool covers(const Outline& outline) const;
    /// The image position of a world point, or nothing when it is behind the eye.
    std::optional<ImagePoint> point(const Vec3& p) const;
    /// The projected segment p-q, clipped to the half-space in front of the eye.
    std::optional<ImageSegment> segment(const Vec3& p, const Vec3& q) const;
    /// The outline of a sphere as seen from the eye (its tangent circle, projected, or
    /// the part of the sphere in front of the near plane); empty when the eye is inside it
    /// or it is entirely behind the near plane.
    Outline silhouette(const Sphere& s, int samples = 64) const;
    /// The outline of the convex hull of two spheres (both silhouettes and their tangent
    /// lines), clipped to the near plane. A sphere holding the eye adds nothing: from
    /// inside, the hull is seen through the other sphere. When the eye lies in the hull
    /// between the two, the hull holds the whole view.
    Outline hull(Sphere a, Sphere b, int samples = 64) const;
    /// The outline of the cone of eye rays within `angle` (radians) of direction `axis`.
    Outline eyeCone(const Vec3& axis, double angle, int samples = 64) const;
    /// The outline of a convex polygon.
    Outline polygon(const Polygon& p) const;
    /// Distance from the eye along the view direction.
    double depth(const Vec3& p) const;
    const Vec3& eye() const { return eye_; }
    double nearPlane() const { return near_; }

private:
    /// Image position of a point at depth >= near_ (no checks).
    ImagePoint image(const Vec3& p) const;
    /// Adds the outline points of the part of sphere `s` in front of the near plane.
    void sphereOutline(const Sphere& s, int samples, Outline& out) const;
    /// The clip rectangle as an outline (or an empty one without a clip).
    Outline whole() const;
    Outline clipped(const Outline& convex) const;
    const RayGenerator& rays_;
    Vec3 eye_, forward_;
    double near_;
    ImageRect clip_;
};

/// Clips a convex outline to a rectangle (Sutherland-Hodgman); the result is convex.
Outline clipConvex(const Outline& outline, const ImageRect& rect);
/// Clips a segment to a rectangle (Liang-Barsky); nothing when it misses it.
std::optional<ImageSegment> clipLine(const ImageSegment& line, const ImageRect& rect);
/// The convex hull of a point set (Andrew's monotone chain), counter-clockwise.
Outline convexHull(Outline points);
/// Whether `p` lies inside `outline` (even-odd rule).
bool contains(const Outline& outline, const ImagePoint& p);

}  // namespace rc
