#include "view/image_projector.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/cone.h"
#include "geometry/student_code.h"

namespace rc {

namespace {
// Two unit vectors perpendicular to `n` and to each other
void basis(const Vec3& n, Vec3& e1, Vec3& e2) {
    const Vec3 other = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    e1 = glm::normalize(glm::cross(n, other));
    e2 = glm::cross(n, e1);
}

/// Direction i of n spread evenly over the unit sphere (a Fibonacci lattice).
Vec3 spreadDirection(int i, int n) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.399963229728653 * i;
    return {rho * std::cos(phi), rho * std::sin(phi), z};
}
}  // namespace

ImageProjector::ImageProjector(const Camera& camera, const RayGenerator& rays)
    : rays_(rays), eye_(camera.from), forward_(glm::normalize(camera.at - camera.from)) {
    near_ = std::max(1e-6, camera.hither);
}

double ImageProjector::depth(const Vec3& p) const { return glm::dot(p - eye_, forward_); }

// [projector-point]
ImagePoint ImageProjector::image(const Vec3& p) const {
    const auto xy = rays_.project(p);
    return xy ? ImagePoint(xy->x + 0.5, xy->y + 0.5) : ImagePoint(0.0);
}

std::optional<ImagePoint> ImageProjector::point(const Vec3& p) const {
    if (depth(p) < near_ * 0.5) return std::nullopt;
    const auto xy = rays_.project(p);
    if (!xy) return std::nullopt;
    return ImagePoint(xy->x + 0.5, xy->y + 0.5);
}

std::optional<ImageSegment> ImageProjector::segment(const Vec3& p, const Vec3& q) const {
    Vec3 a = p, b = q;
    const double da = depth(a), db = depth(b);
    if (da < near_ && db < near_) return std::nullopt;
    // Clip the part behind the near plane, then the part outside the view
    if (da < near_) a = a + (b - a) * ((near_ - da) / (db - da));
    if (db < near_) b = b + (a - b) * ((near_ - db) / (da - db));
    const ImageSegment l{image(a), image(b)};
    if (clip_.empty()) return l;
    return clipLine(l, clip_);
}
// [projector-point]

Outline ImageProjector::whole() const {
    if (clip_.empty()) return {};
    return {{clip_.left, clip_.top}, {clip_.right, clip_.top}, {clip_.right, clip_.bottom}, {clip_.left, clip_.bottom}};
}

Outline ImageProjector::clipped(const Outline& convex) const {
    if (clip_.empty() || convex.size() < 3) return convex;
    return clipConvex(convex, clip_);
}

bool ImageProjector::covers(const Outline& poly) const {
    if (clip_.empty() || poly.size() < 3) return false;
    const double ex = 1e-6 * clip_.width(), ey = 1e-6 * clip_.height();
    for (const ImagePoint& c : {ImagePoint(clip_.left + ex, clip_.top + ey), ImagePoint(clip_.right - ex, clip_.top + ey),
                                ImagePoint(clip_.right - ex, clip_.bottom - ey), ImagePoint(clip_.left + ex, clip_.bottom - ey)})
        if (!contains(poly, c)) return false;
    return true;
}

// [projector-sphere]
void ImageProjector::sphereOutline(const Sphere& s, int samples, Outline& out) const {
    const Vec3 v = s.c - eye_;
    const double d2 = glm::dot(v, v);
    if (d2 <= s.r * s.r) return;  // the eye is inside: no outline
    const double dc = depth(s.c);
    if (dc + s.r < near_) return;  // wholly behind the near plane
    if (s.r <= 0.0) {
        out.push_back(image(s.c));
        return;
    }
    // The eye sees the sphere's tangent circle: centre c - v r^2/d^2, radius r sqrt(d^2 - r^2)/d
    const Vec3 centre = s.c - v * (s.r * s.r / d2);
    const double rho = s.r * std::sqrt(d2 - s.r * s.r) / std::sqrt(d2);
    Vec3 e1, e2;
    basis(glm::normalize(v), e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        const Vec3 p = centre + rho * (std::cos(a) * e1 + std::sin(a) * e2);
        if (depth(p) >= near_) out.push_back(image(p));
    }
    if (dc - s.r >= near_) return;
    // The sphere reaches behind the near plane: what is seen is the cap in front of it,
    // outlined by the tangent circle's front part and the circle the near plane cuts
    const double h = near_ - dc;
    const double cut = std::sqrt(std::max(0.0, s.r * s.r - h * h));
    const Vec3 q = s.c + forward_ * h;
    basis(forward_, e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        out.push_back(image(q + cut * (std::cos(a) * e1 + std::sin(a) * e2)));
    }
}

Outline ImageProjector::silhouette(const Sphere& s, int samples) const {
    Outline out;
    sphereOutline(s, samples, out);
    if (out.size() < 3) return out;
    return clipped(convexHull(out));
}

Outline ImageProjector::hull(Sphere a, Sphere b, int samples) const {
    const Hull h(a, b);
    // A student build with tutorial 03 open draws the student's own rc::Hull: its boundary
    // found by bisection on Hull::distance() along rays from a point inside it, projected
    if (isStudents(3)) {
        Vec3 m = (a.c + b.c) * 0.5;
        if (h.distance(m) > 0.0) m = a.r >= b.r ? a.c : b.c;
        const double reach = 2.0 * (glm::length(b.c - a.c) + a.r + b.r) + 1.0;
        Outline pts;
        const int n = 8 * samples;
        for (int i = 0; i < n; ++i) {
            const Vec3 u = spreadDirection(i, n);
            double lo = 0.0, hi = reach;
            if (h.distance(m + hi * u) <= 0.0) continue;
            for (int k = 0; k < 48; ++k) (h.distance(m + 0.5 * (lo + hi) * u) <= 0.0 ? lo : hi) = 0.5 * (lo + hi);
            if (const auto p = point(m + lo * u)) pts.push_back(*p);
        }
        if (pts.size() < 3) return pts;
        return clipped(convexHull(pts));
    }
    auto holdsEye = [&](const Sphere& s) { return glm::length(s.c - eye_) <= s.r; };
    const bool ia = holdsEye(a), ib = holdsEye(b);
    if (ia && ib) return {};
    if (ia) return silhouette(b, samples);
    if (ib) return silhouette(a, samples);
    // The hull holds the eye between the two: it fills the whole view
    if (h.distance(eye_) <= 0.0) return whole();
    Outline pts;
    const bool inFront = depth(a.c) - a.r >= near_ && depth(b.c) - b.r >= near_;
    if (inFront) {
        // In front of the near plane, the hull's outline is that of the two silhouettes
        sphereOutline(a, samples, pts);
        sphereOutline(b, samples, pts);
    } else {
        // Clipped by the near plane. The hull is the convex hull of the two spheres' points,
        // so its part in front of the plane is that of the points in front and of the
        // crossings of the segments joining points on either side: sampled on both spheres
        std::vector<Vec3> front, behind;
        for (const Sphere& s : {a, b}) {
            const int n = s.r > 0.0 ? 2 * samples : 1;
            for (int i = 0; i < n; ++i) {
                const Vec3 p = s.c + s.r * spreadDirection(i, n);
                (depth(p) >= near_ ? front : behind).push_back(p);
            }
        }
        for (const Vec3& p : front) {
            pts.push_back(image(p));
            const double dp = depth(p);
            for (const Vec3& q : behind) pts.push_back(image(p + (q - p) * ((dp - near_) / (dp - depth(q)))));
        }
    }
    if (pts.size() < 3) return pts;
    return clipped(convexHull(pts));
}
// [projector-sphere]

Outline ImageProjector::eyeCone(const Vec3& axis, double angle, int samples) const {
    Outline out;
    if (!(angle > 0.0) || angle >= M_PI / 2) return out;
    Vec3 e1, e2;
    const Vec3 n = glm::normalize(axis);
    basis(n, e1, e2);
    // Directions nearly level with the eye go far off the image: they are cut where they
    // reach a small forward component, then the view clips them
    constexpr double kLevel = 1e-4;
    auto dir = [&](int i) {
        const double a = 2.0 * M_PI * i / samples;
        return Vec3(std::cos(angle) * n + std::sin(angle) * (std::cos(a) * e1 + std::sin(a) * e2));
    };
    for (int i = 0; i < samples; ++i) {
        const Vec3 d = dir(i), next = dir((i + 1) % samples);
        const double z = glm::dot(d, forward_), zn = glm::dot(next, forward_);
        if (z >= kLevel) out.push_back(image(eye_ + d / z));
        if ((z >= kLevel) != (zn >= kLevel)) {
            const Vec3 m = d + (next - d) * ((kLevel - z) / (zn - z));
            out.push_back(image(eye_ + m / kLevel));
        }
    }
    if (out.size() < 3) return {};
    return clipped(convexHull(out));
}

Outline ImageProjector::polygon(const Polygon& poly) const {
    // Clip in 3D to the near plane (Sutherland-Hodgman), then project and clip to the view
    std::vector<Vec3> in(poly.vertices.begin(), poly.vertices.end()), kept;
    const int n = int(in.size());
    for (int i = 0; i < n; ++i) {
        const Vec3& a = in[i];
        const Vec3& b = in[(i + 1) % n];
        const double da = depth(a), db = depth(b);
        if (da >= near_) kept.push_back(a);
        if ((da >= near_) != (db >= near_)) kept.push_back(a + (b - a) * ((near_ - da) / (db - da)));
    }
    Outline out;
    for (const Vec3& p : kept) out.push_back(image(p));
    if (out.size() < 3) return out;
    return clipped(convexHull(out));
}

Outline clipConvex(const Outline& poly, const ImageRect& rect) {
    Outline out = poly;
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
    // One half-plane per side: keep what is inside, add the crossings
    auto pass = [&](auto inside, auto cross) {
        Outline next;
        const int n = int(out.size());
        for (int i = 0; i < n; ++i) {
            const ImagePoint& a = out[i];
            const ImagePoint& b = out[(i + 1) % n];
            const bool ia = inside(a), ib = inside(b);
            if (ia) next.push_back(a);
            if (ia != ib) next.push_back(cross(a, b));
        }
        out.swap(next);
    };
    const double l = rect.left, r = rect.right, t = rect.top, btm = rect.bottom;
    auto atX = [](const ImagePoint& a, const ImagePoint& b, double x) {
        return ImagePoint(x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x));
    };
    auto atY = [](const ImagePoint& a, const ImagePoint& b, double y) {
        return ImagePoint(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y);
    };
    pass([&](const ImagePoint& p) { return p.x >= l; }, [&](const ImagePoint& a, const ImagePoint& b) { return atX(a, b, l); });
    pass([&](const ImagePoint& p) { return p.x <= r; }, [&](const ImagePoint& a, const ImagePoint& b) { return atX(a, b, r); });
    pass([&](const ImagePoint& p) { return p.y >= t; }, [&](const ImagePoint& a, const ImagePoint& b) { return atY(a, b, t); });
    pass([&](const ImagePoint& p) { return p.y <= btm; }, [&](const ImagePoint& a, const ImagePoint& b) { return atY(a, b, btm); });
    return out;
}

std::optional<ImageSegment> clipLine(const ImageSegment& line, const ImageRect& rect) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = line.b.x - line.a.x, dy = line.b.y - line.a.y;
    auto edge = [&](double p, double q) {
        if (p == 0.0) return q >= 0.0;
        const double r = q / p;
        if (p < 0.0) {
            if (r > t1) return false;
            t0 = std::max(t0, r);
        } else {
            if (r < t0) return false;
            t1 = std::min(t1, r);
        }
        return true;
    };
    const ImagePoint a = line.a;
    if (!edge(-dx, a.x - rect.left) || !edge(dx, rect.right - a.x) || !edge(-dy, a.y - rect.top) ||
        !edge(dy, rect.bottom - a.y))
        return std::nullopt;
    if (t0 > t1) return std::nullopt;
    return ImageSegment{a + ImagePoint(dx, dy) * t0, a + ImagePoint(dx, dy) * t1};
}

Outline convexHull(Outline p) {
    if (p.size() < 3) return p;
    std::sort(p.begin(), p.end(), [](const ImagePoint& a, const ImagePoint& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    auto cross = [](const ImagePoint& o, const ImagePoint& a, const ImagePoint& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    Outline h(2 * p.size());
    int k = 0;
    for (int i = 0; i < int(p.size()); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (int i = int(p.size()) - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(std::size_t(k - 1));
    return h;
}

bool contains(const Outline& outline, const ImagePoint& p) {
    bool inside = false;
    const std::size_t n = outline.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const ImagePoint& a = outline[i];
        const ImagePoint& b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

}  // namespace rc
