#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"

namespace rc {

namespace {

/// Twice the signed area of triangle (a, b, c) in the plane: > 0 when it turns left.
double orient(double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// Do closed segments p0-p1 and q0-q1 (2D) share a point?
bool segmentsMeet(const double* p0, const double* p1, const double* q0, const double* q1) {
    const double d1 = orient(q0[0], q0[1], q1[0], q1[1], p0[0], p0[1]);
    const double d2 = orient(q0[0], q0[1], q1[0], q1[1], p1[0], p1[1]);
    const double d3 = orient(p0[0], p0[1], p1[0], p1[1], q0[0], q0[1]);
    const double d4 = orient(p0[0], p0[1], p1[0], p1[1], q1[0], q1[1]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    // Touching or collinear: a point of one on the other
    auto onSegment = [](const double* a, const double* b, const double* p) {
        return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
               std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
    };
    return (d1 == 0 && onSegment(q0, q1, p0)) || (d2 == 0 && onSegment(q0, q1, p1)) ||
           (d3 == 0 && onSegment(p0, p1, q0)) || (d4 == 0 && onSegment(p0, p1, q1));
}

/// Does the outline (2D, `xy` holds x0 y0 x1 y1 ...) cross or touch itself anywhere but
/// where neighbouring edges meet? A sweep over the edges sorted by their least x: only
/// edges whose x ranges overlap are compared.
bool crossesItself(const std::vector<double>& xy) {
    const std::size_t n = xy.size() / 2;
    auto v = [&](std::size_t i) { return &xy[2 * (i % n)]; };
    std::vector<std::size_t> edges(n);
    std::iota(edges.begin(), edges.end(), 0);
    auto lo = [&](std::size_t e) { return std::min(v(e)[0], v(e + 1)[0]); };
    auto hi = [&](std::size_t e) { return std::max(v(e)[0], v(e + 1)[0]); };
    std::sort(edges.begin(), edges.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t e = edges[i];
        for (std::size_t j = i + 1; j < n && lo(edges[j]) <= hi(e); ++j) {
            const std::size_t f = edges[j];
            const bool neighbours = (e + 1) % n == f || (f + 1) % n == e;
            if (neighbours) {
                // Neighbours share one vertex; they may not fold back over each other
                const std::size_t shared = (e + 1) % n == f ? f : e;
                const double* a = v(shared + n - 1);
                const double* s = v(shared);
                const double* b = v(shared + 1);
                if (n > 3 && orient(a[0], a[1], s[0], s[1], b[0], b[1]) == 0 &&
                    (b[0] - s[0]) * (a[0] - s[0]) + (b[1] - s[1]) * (a[1] - s[1]) > 0)
                    return true;
                continue;
            }
            if (segmentsMeet(v(e), v(e + 1), v(f), v(f + 1))) return true;
        }
    }
    return false;
}

}  // namespace

std::optional<std::string> makePolygon(std::vector<Vec3> vertices, std::vector<Vec3> normals,
                                       Polygon& out) {
    if (vertices.size() < 3) return "a polygon needs at least 3 vertices";
    // Newell's method: robust normal for any winding, convex or not
    Vec3 n(0.0);
    double extent = 0.0;
    for (size_t i = 0; i < vertices.size(); ++i) {
        const Vec3& a = vertices[i];
        const Vec3& b = vertices[(i + 1) % vertices.size()];
        n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        extent = std::max(extent, glm::length(b - a));
    }
    // Scaled first: with coordinates up to 1e100 (the reader's limit) n reaches 1e200 and
    // its squared length would overflow
    const double big = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    const double len = big > 0.0 ? big * glm::length(n / big) : 0.0;
    if (!(len > 1e-12 * extent * extent) || !std::isfinite(len))
        return std::string(kZeroAreaPolygon);
    n /= len;
    double offset = 0.0;
    for (const Vec3& v : vertices) offset += glm::dot(n, v);
    offset /= double(vertices.size());
    // Planarity: every vertex on the plane
    for (const Vec3& v : vertices)
        if (std::abs(glm::dot(n, v) - offset) > 1e-6 * std::max(1.0, extent)) return "polygon is not planar";
    // Simplicity: the outline, seen along the normal, never crosses itself
    const int drop = std::abs(n.x) > std::abs(n.y) ? (std::abs(n.x) > std::abs(n.z) ? 0 : 2)
                                                   : (std::abs(n.y) > std::abs(n.z) ? 1 : 2);
    std::vector<double> xy;
    xy.reserve(2 * vertices.size());
    for (const Vec3& v : vertices) {
        xy.push_back(v[(drop + 1) % 3]);
        xy.push_back(v[(drop + 2) % 3]);
    }
    if (crossesItself(xy)) return "polygon crosses itself (its outline is not simple)";
    // Convexity: every turn the same way as the normal
    bool convex = true;
    for (size_t i = 0; i < vertices.size() && convex; ++i) {
        const Vec3& a = vertices[i];
        const Vec3& b = vertices[(i + 1) % vertices.size()];
        const Vec3& c = vertices[(i + 2) % vertices.size()];
        convex = glm::dot(glm::cross(b - a, c - b), n) >= -1e-12 * extent * extent;
    }
    for (Vec3& vn : normals) {
        const double l = glm::length(vn);
        if (!(l > 0.0) || !std::isfinite(l)) return "zero or non-finite vertex normal";
        vn /= l;
    }
    out.vertices = std::move(vertices);
    out.vertexNormals = std::move(normals);
    out.normal = n;
    out.offset = offset;
    out.convex = convex;
    out.bound = boundingSphere(out);
    return std::nullopt;
}

double intersectPolygon(const Ray& ray, const Polygon& poly, bool fromThis) {
    // [polygon-hit]
    // A ray leaving a plane cannot meet it again
    if (fromThis) return kNoHit;
    const double denom = glm::dot(poly.normal, ray.d);
    if (denom == 0.0) return kNoHit;
    const double t = (poly.offset - glm::dot(poly.normal, ray.o)) / denom;
    if (!(t > 0.0)) return kNoHit;
    // Many vertices: first a cheap rejection by the bounding sphere, measured from the line
    const std::size_t n = poly.vertices.size();
    if (n > 8) {
        const Vec3 f = poly.bound.c - ray.o;
        const Vec3 l = f - glm::dot(f, ray.d) * ray.d;
        const double margin = 1e-9 * (poly.bound.r + glm::length(f));
        if (glm::dot(l, l) > (poly.bound.r + margin) * (poly.bound.r + margin)) return kNoHit;
    }
    // The ray's frame: z along the ray's largest component, the vertices sheared onto the
    // plane through the origin across the ray, where the ray itself is the point (0, 0)
    const int kz = std::abs(ray.d.x) > std::abs(ray.d.y) ? (std::abs(ray.d.x) > std::abs(ray.d.z) ? 0 : 2)
                                                         : (std::abs(ray.d.y) > std::abs(ray.d.z) ? 1 : 2);
    const int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
    const double sx = ray.d[kx] / ray.d[kz], sy = ray.d[ky] / ray.d[kz];
    auto project = [&](const Vec3& v, double& x, double& y) {
        const double z = v[kz] - ray.o[kz];
        x = (v[kx] - ray.o[kx]) - sx * z;
        y = (v[ky] - ray.o[ky]) - sy * z;
    };
    // Count the edges that cross the half-line x > 0, y = 0. An edge is decided from its
    // lower and upper end, in that order whichever polygon it belongs to: shared edges agree
    bool inside = false;
    double px, py;
    project(poly.vertices[n - 1], px, py);
    for (std::size_t i = 0; i < n; ++i) {
        double cx, cy;
        project(poly.vertices[i], cx, cy);
        if ((py > 0.0) != (cy > 0.0)) {
            const double lx = py > 0.0 ? cx : px, ly = py > 0.0 ? cy : py;  // lower end
            const double ux = py > 0.0 ? px : cx, uy = py > 0.0 ? py : cy;  // upper end
            if (lx * uy - ly * ux > 0.0) inside = !inside;
        }
        px = cx;
        py = cy;
    }
    return inside ? t : kNoHit;
    // [polygon-hit]
}

Sphere boundingSphere(const Polygon& poly) {
    Vec3 lo = poly.vertices.front(), hi = lo;
    for (const Vec3& v : poly.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    Sphere s{0.5 * (lo + hi), 0.0};
    for (const Vec3& v : poly.vertices) s.r = std::max(s.r, glm::length(v - s.c));
    s.r *= 1.0 + 1e-12;
    return s;
}

Vec3 polygonNormal(const Polygon& poly, const Vec3& p) {
    if (poly.vertexNormals.empty()) return poly.normal;
    // Inverse-distance weights: smooth enough for pp patches, exact at the vertices
    Vec3 n(0.0);
    for (size_t i = 0; i < poly.vertices.size(); ++i) {
        const double d = glm::length(p - poly.vertices[i]);
        if (d == 0.0) return poly.vertexNormals[i];
        n += poly.vertexNormals[i] / d;
    }
    const double l = glm::length(n);
    return l > 0.0 ? n / l : poly.normal;
}

}  // namespace rc
