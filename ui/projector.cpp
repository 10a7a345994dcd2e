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
    // Clip the part behind the near plane
    if (da < near_) a = a + (b - a) * ((near_ - da) / (db - da));
    if (db < near_) b = b + (a - b) * ((near_ - db) / (da - db));
    const auto pa = point(a), pb = point(b);
    if (!pa || !pb) return std::nullopt;
    return QLineF(*pa, *pb);
}

QPolygonF Projector::silhouette(const rc::Sphere& s, int samples) const {
    QPolygonF out;
    const rc::Vec3 v = s.c - eye_;
    const double d2 = glm::dot(v, v);
    if (d2 <= s.r * s.r) return out;
    if (s.r <= 0.0) {
        if (auto p = point(s.c)) out << *p;
        return out;
    }
    // The eye sees the sphere's tangent circle: centre c - v r^2/d^2, radius r sqrt(d^2 - r^2)/d
    const rc::Vec3 centre = s.c - v * (s.r * s.r / d2);
    const double rho = s.r * std::sqrt(d2 - s.r * s.r) / std::sqrt(d2);
    rc::Vec3 e1, e2;
    basis(glm::normalize(v), e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        if (auto p = point(centre + rho * (std::cos(a) * e1 + std::sin(a) * e2))) out << *p;
    }
    return out;
}

QPolygonF Projector::hull(rc::Sphere a, rc::Sphere b, int samples) const {
    auto holdsEye = [&](const rc::Sphere& s) { return glm::length(s.c - eye_) <= s.r; };
    // A sphere reaching behind the near plane: slide it (and blend its radius) towards the
    // other one until it is in front; what is cut off lies off the image anyway
    auto pull = [&](rc::Sphere& s, const rc::Sphere& towards) {
        const double target = near_ * 4.0;
        const double ds = depth(s.c) - s.r, dt = depth(towards.c) - towards.r;
        if (ds >= target || holdsEye(s)) return;
        if (dt <= target) return;
        const double f = (target - ds) / (dt - ds);
        s.c = s.c + (towards.c - s.c) * f;
        s.r = s.r + (towards.r - s.r) * f;
    };
    pull(a, b);
    pull(b, a);
    QPolygonF pts;
    if (!holdsEye(a)) pts << silhouette(a, samples);
    if (!holdsEye(b)) pts << silhouette(b, samples);
    return convexHull(pts);
}

QPolygonF Projector::eyeCone(const rc::Vec3& axis, double angle, int samples) const {
    QPolygonF out;
    if (!(angle > 0.0) || angle >= M_PI / 2) return out;
    rc::Vec3 e1, e2;
    const rc::Vec3 n = glm::normalize(axis);
    basis(n, e1, e2);
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        const rc::Vec3 d = std::cos(angle) * n + std::sin(angle) * (std::cos(a) * e1 + std::sin(a) * e2);
        if (auto p = point(eye_ + d)) out << *p;
    }
    return out;
}

QPolygonF Projector::polygon(const rc::Polygon& poly) const {
    QPolygonF out;
    const int n = int(poly.vertices.size());
    for (int i = 0; i < n; ++i) {
        if (auto l = segment(poly.vertices[i], poly.vertices[(i + 1) % n])) out << l->p1() << l->p2();
    }
    return out;
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
