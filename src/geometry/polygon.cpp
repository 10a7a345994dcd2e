#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"

namespace rc {

std::optional<std::string> makePolygon(std::vector<Vec3> vertices, std::vector<Vec3> normals,
                                       Polygon& out) {
    if (vertices.size() < 3) return "a polygon needs at least 3 vertices";
    // Newell's method: robust normal for any winding
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
        return "degenerate polygon (collinear or coincident vertices)";
    n /= len;
    double offset = 0.0;
    for (const Vec3& v : vertices) offset += glm::dot(n, v);
    offset /= double(vertices.size());
    // Planarity and convexity: every vertex on the plane, every turn the same way
    for (size_t i = 0; i < vertices.size(); ++i) {
        if (std::abs(glm::dot(n, vertices[i]) - offset) > 1e-6 * std::max(1.0, extent))
            return "polygon is not planar";
        const Vec3& a = vertices[i];
        const Vec3& b = vertices[(i + 1) % vertices.size()];
        const Vec3& c = vertices[(i + 2) % vertices.size()];
        if (glm::dot(glm::cross(b - a, c - b), n) < -1e-12 * extent * extent)
            return "polygon is not convex";
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
    // Inside a convex polygon: the point is on the inner side of every edge
    const Vec3 p = ray.at(t);
    const size_t n = poly.vertices.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = poly.vertices[i];
        const Vec3& b = poly.vertices[(i + 1) % n];
        if (glm::dot(glm::cross(b - a, p - a), poly.normal) < 0.0) return kNoHit;
    }
    return t;
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
