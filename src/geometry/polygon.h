#pragma once
/// \file
/// \brief Planar polygons (NFF `p` and `pp`): convex or concave, any simple outline.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace rc {

/// A simple planar polygon, convex or not. The plane normal comes from Newell's method, so
/// either winding works; `vertexNormals` is empty unless the polygon came from `pp`.
struct Polygon {
    std::vector<Vec3> vertices;
    std::vector<Vec3> vertexNormals;
    Vec3 normal{0.0, 0.0, 1.0};  ///< unit plane normal
    double offset = 0.0;         ///< plane: dot(normal, x) = offset
    bool convex = true;          ///< every turn of the outline goes the same way
    Sphere bound;                ///< holds every vertex (boundingSphere())
};

/// makePolygon's explanation for a polygon of zero area (collinear or coincident vertices):
/// no ray can hit it, so a reader may skip it rather than refuse the scene.
inline constexpr std::string_view kZeroAreaPolygon = "degenerate polygon (collinear or coincident vertices)";

/// Builds a polygon from its vertices (and optional per-vertex normals). Returns an
/// explanation instead when the polygon has fewer than three vertices, is degenerate
/// (zero area: kZeroAreaPolygon), is not planar, crosses itself, or has a zero vertex normal.
std::optional<std::string> makePolygon(std::vector<Vec3> vertices, std::vector<Vec3> normals,
                                       Polygon& out);

/// Hit distance of a ray with the polygon, or kNoHit. A ray leaving the polygon's
/// plane cannot meet that plane again: pass `fromThis` and it is skipped.
///
/// Watertight: whether the ray passes inside is decided in the ray's own frame (the
/// vertices projected along the ray, as Woop, Benthin and Wald 2013 do for triangles) by
/// a crossing count whose every edge decision depends on the edge alone. Two polygons
/// that share an edge or a vertex project it identically and decide it alike, so a ray
/// through a shared edge of a closed mesh meets exactly one of its faces there.
double intersectPolygon(const Ray& ray, const Polygon& poly, bool fromThis);

/// The smallest sphere around the vertices' bounding box centre holding every vertex:
/// how polygons take part in safety cylinders and blocker hulls.
Sphere boundingSphere(const Polygon& poly);

/// Shading normal at point `p` of the polygon: interpolated for `pp`, else the plane's.
Vec3 polygonNormal(const Polygon& poly, const Vec3& p);

}  // namespace rc
