#include "projector.h"

#include <algorithm>
#include <cmath>

#include <QLineF>
#include <glm/geometric.hpp>

namespace rcgui {

namespace {
// Two unit vectors perpendicular to `n` and to each other
void basis(const rc::Vec3& n, rc::Vec3& e1, rc::Vec3& e2) {
    const rc::Vec3 other = std::abs(n.x) < 0.9 ? rc::Vec3(1, 0, 0) : rc::Vec3(0, 1, 0);
    e1 = glm::normalize(glm::cross(n, other));
    e2 = glm::cross(n, e1);
}
}  // namespace

Projector::Projector(const rc::Camera& camera, const rc::RayGenerator& rays)
    : rays_(rays), eye_(camera.from), forward_(glm::normalize(camera.at - camera.from)) {
    near_ = std::max(1e-6, camera.hither);
}

double Projector::depth(const rc::Vec3& p) const { return glm::dot(p - eye_, forward_); }

// [projector-point]
QPointF Projector::image(const rc::Vec3& p) const {
    const auto xy = rays_.project(p);
    return xy ? QPointF(xy->x + 0.5, xy->y + 0.5) : QPointF();
}

std::optional<QPointF> Projector::point(const rc::Vec3& p) const {
    if (depth(p) < near_ * 0.5) return std::nullopt;
    const auto xy = rays_.project(p);
    if (!xy) return std::nullopt;
    return QPointF(xy->x + 0.5, xy->y + 0.5);
}

std::optional<QLineF> Projector::segment(const rc::Vec3& p, const rc::Vec3& q) const {
    rc::Vec3 a = p, b = q;
    const double da = depth(a), db = depth(b);
    if (da < near_ && db < near_) return std::nullopt;
    // Clip the part behind the near plane, then the part outside the view
    if (da < near_) a = a + (b - a) * ((near_ - da) / (db - da));
    if (db < near_) b = b + (a - b) * ((near_ - db) / (da - db));
    const QLineF l(image(a), image(b));
    if (clip_.isNull()) return l;
    return clipLine(l, clip_);
}
// [projector-point]

QPolygonF Projector::whole() const {
    if (clip_.isNull()) return {};
    return QPolygonF({clip_.topLeft(), clip_.topRight(), clip_.bottomRight(), clip_.bottomLeft()});
}

QPolygonF Projector::clipped(const QPolygonF& convex) const {
    if (clip_.isNull() || convex.size() < 3) return convex;
    return clipConvex(convex, clip_);
}

bool Projector::covers(const QPolygonF& poly) const {
    if (clip_.isNull() || poly.size() < 3) return false;
    const QRectF inner = clip_.adjusted(1e-6 * clip_.width(), 1e-6 * clip_.height(), -1e-6 * clip_.width(),
                                        -1e-6 * clip_.height());
    for (const QPointF& c : {inner.topLeft(), inner.topRight(), inner.bottomRight(), inner.bottomLeft()})
        if (!poly.containsPoint(c, Qt::OddEvenFill)) return false;
    return true;
}

// [projector-sphere]
void Projector::sphereOutline(const rc::Sphere& s, int samples, QPolygonF& out) const {
    const rc::Vec3 v = s.c - eye_;
    const double d2 = glm::dot(v, v);
    if (d2 <= s.r * s.r) return;  // the eye is inside: no outline
    const double dc = depth(s.c);
    if (dc + s.r < near_) return;  // wholly behind the near plane
    if (s.r <= 0.0) {
        out << image(s.c);
        return;
    }
    // The eye sees the sphere's tangent circle: centre c - v r^2/d^2, radius r sqrt(d^2 - r^2)/d
    const rc::Vec3 centre = s.c - v * (s.r * s.r / d2);
    const double rho = s.r * std::sqrt(d2 - s.r * s.r) / std::sqrt(d2);
    rc::Vec3 e1, e2;
    basis(glm::normalize(v), e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        const rc::Vec3 p = centre + rho * (std::cos(a) * e1 + std::sin(a) * e2);
        if (depth(p) >= near_) out << image(p);
    }
    if (dc - s.r >= near_) return;
    // The sphere reaches behind the near plane: what is seen is the cap in front of it,
    // outlined by the tangent circle's front part and the circle the near plane cuts
    const double h = near_ - dc;
    const double cut = std::sqrt(std::max(0.0, s.r * s.r - h * h));
    const rc::Vec3 q = s.c + forward_ * h;
    basis(forward_, e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        out << image(q + cut * (std::cos(a) * e1 + std::sin(a) * e2));
    }
}

QPolygonF Projector::silhouette(const rc::Sphere& s, int samples) const {
    QPolygonF out;
    sphereOutline(s, samples, out);
    if (out.size() < 3) return out;
    return clipped(convexHull(out));
}

QPolygonF Projector::hull(rc::Sphere a, rc::Sphere b, int samples) const {
    auto holdsEye = [&](const rc::Sphere& s) { return glm::length(s.c - eye_) <= s.r; };
    const bool ia = holdsEye(a), ib = holdsEye(b);
    if (ia && ib) return {};
    if (ia) return silhouette(b, samples);
    if (ib) return silhouette(a, samples);
    // The hull of two balls is the union of the balls between them (centres and radii
    // blended): when one of those holds the eye, the hull fills the whole view
    constexpr int kSteps = 24;
    for (int k = 1; k < kSteps; ++k) {
        const double f = double(k) / kSteps;
        if (holdsEye({a.c + (b.c - a.c) * f, a.r + (b.r - a.r) * f})) return whole();
    }
    QPolygonF pts;
    const bool inFront = depth(a.c) - a.r >= near_ && depth(b.c) - b.r >= near_;
    if (inFront) {
        // In front of the near plane, the hull's outline is that of the two silhouettes
        sphereOutline(a, samples, pts);
        sphereOutline(b, samples, pts);
    } else {
        // Clipped by the near plane: the outlines of the blended balls' front parts
        for (int k = 0; k <= kSteps; ++k) {
            const double f = double(k) / kSteps;
            sphereOutline({a.c + (b.c - a.c) * f, a.r + (b.r - a.r) * f}, samples / 2, pts);
        }
    }
    if (pts.size() < 3) return pts;
    return clipped(convexHull(pts));
}
// [projector-sphere]

QPolygonF Projector::eyeCone(const rc::Vec3& axis, double angle, int samples) const {
    QPolygonF out;
    if (!(angle > 0.0) || angle >= M_PI / 2) return out;
    rc::Vec3 e1, e2;
    const rc::Vec3 n = glm::normalize(axis);
    basis(n, e1, e2);
    // Directions nearly level with the eye go far off the image: they are cut where they
    // reach a small forward component, then the view clips them
    constexpr double kLevel = 1e-4;
    auto dir = [&](int i) {
        const double a = 2.0 * M_PI * i / samples;
        return rc::Vec3(std::cos(angle) * n + std::sin(angle) * (std::cos(a) * e1 + std::sin(a) * e2));
    };
    for (int i = 0; i < samples; ++i) {
        const rc::Vec3 d = dir(i), next = dir((i + 1) % samples);
        const double z = glm::dot(d, forward_), zn = glm::dot(next, forward_);
        if (z >= kLevel) out << image(eye_ + d / z);
        if ((z >= kLevel) != (zn >= kLevel)) {
            const rc::Vec3 m = d + (next - d) * ((kLevel - z) / (zn - z));
            out << image(eye_ + m / kLevel);
        }
    }
    if (out.size() < 3) return {};
    return clipped(convexHull(out));
}

QPolygonF Projector::polygon(const rc::Polygon& poly) const {
    // Clip in 3D to the near plane (Sutherland-Hodgman), then project and clip to the view
    std::vector<rc::Vec3> in(poly.vertices.begin(), poly.vertices.end()), kept;
    const int n = int(in.size());
    for (int i = 0; i < n; ++i) {
        const rc::Vec3& a = in[i];
        const rc::Vec3& b = in[(i + 1) % n];
        const double da = depth(a), db = depth(b);
        if (da >= near_) kept.push_back(a);
        if ((da >= near_) != (db >= near_)) kept.push_back(a + (b - a) * ((near_ - da) / (db - da)));
    }
    QPolygonF out;
    for (const rc::Vec3& p : kept) out << image(p);
    if (out.size() < 3) return out;
    return clipped(convexHull(out));
}

QPolygonF clipConvex(const QPolygonF& poly, const QRectF& rect) {
    QPolygonF out = poly;
    if (out.size() > 1 && out.front() == out.back()) out.removeLast();
    // One half-plane per side: keep what is inside, add the crossings
    auto pass = [&](auto inside, auto cross) {
        QPolygonF next;
        const int n = int(out.size());
        for (int i = 0; i < n; ++i) {
            const QPointF& a = out[i];
            const QPointF& b = out[(i + 1) % n];
            const bool ia = inside(a), ib = inside(b);
            if (ia) next << a;
            if (ia != ib) next << cross(a, b);
        }
        out.swap(next);
    };
    const double l = rect.left(), r = rect.right(), t = rect.top(), btm = rect.bottom();
    auto atX = [](const QPointF& a, const QPointF& b, double x) {
        return QPointF(x, a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x()));
    };
    auto atY = [](const QPointF& a, const QPointF& b, double y) {
        return QPointF(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()), y);
    };
    pass([&](const QPointF& p) { return p.x() >= l; }, [&](const QPointF& a, const QPointF& b) { return atX(a, b, l); });
    pass([&](const QPointF& p) { return p.x() <= r; }, [&](const QPointF& a, const QPointF& b) { return atX(a, b, r); });
    pass([&](const QPointF& p) { return p.y() >= t; }, [&](const QPointF& a, const QPointF& b) { return atY(a, b, t); });
    pass([&](const QPointF& p) { return p.y() <= btm; }, [&](const QPointF& a, const QPointF& b) { return atY(a, b, btm); });
    return out;
}

std::optional<QLineF> clipLine(const QLineF& line, const QRectF& rect) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = line.dx(), dy = line.dy();
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
    const QPointF a = line.p1();
    if (!edge(-dx, a.x() - rect.left()) || !edge(dx, rect.right() - a.x()) || !edge(-dy, a.y() - rect.top()) ||
        !edge(dy, rect.bottom() - a.y()))
        return std::nullopt;
    if (t0 > t1) return std::nullopt;
    return QLineF(a + QPointF(dx, dy) * t0, a + QPointF(dx, dy) * t1);
}

QPolygonF convexHull(QPolygonF p) {
    if (p.size() < 3) return p;
    std::sort(p.begin(), p.end(), [](const QPointF& a, const QPointF& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    auto cross = [](const QPointF& o, const QPointF& a, const QPointF& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    QPolygonF h(2 * p.size());
    int k = 0;
    for (int i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (int i = int(p.size()) - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

}  // namespace rcgui
