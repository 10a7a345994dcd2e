#pragma once
/// \file
/// \brief Long double references for ray-object hits, and the side-by-side comparison of
/// intersection formulas (textbook and stable, float and double) that
/// `raycache stability --intersection` prints.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/intersection.h"
#include "geometry/polygon.h"
#include "scene/scene.h"

namespace rc {

/// Nearest hit of a ray and a sphere in long double, from the same double inputs, with
/// the same start rules as intersectSphere(). The direction need not be exactly unit.
long double preciseSphereHit(const Ray& ray, const Sphere& s, Start start);

/// Hit distance of a ray and a polygon in long double; the plane comes from the
/// vertices themselves (not from the double normal and offset).
long double precisePolygonHit(const Ray& ray, const Polygon& poly, bool fromThis);

/// Scene::intersect() in long double.
long double preciseHit(const Scene& scene, const Ray& ray, int id, const RayOrigin& origin);

/// One row of the intersection table: a formula at a precision on one stiff case.
struct IntersectionRow {
    std::string stiffCase;    ///< e.g. "r=1e-3 sphere 1e6 away"
    std::string formula;      ///< "textbook" | "stable"
    std::string precision;    ///< "float" | "double" | "long double"
    double maxRelError = 0;   ///< of t, over rays both it and the reference hit
    double medianRelError = 0;
    std::int64_t rays = 0;
    std::int64_t wrongHits = 0;  ///< hit where the reference misses, or the reverse
    double nsPerTest = 0;
};

/// The stiff cases of the comparison: a name and what makes each hard.
std::vector<std::pair<std::string, std::string>> intersectionCases();

/// Runs every formula and precision on `raysPerCase` seeded random rays per case.
std::vector<IntersectionRow> compareIntersections(int raysPerCase = 4096, std::uint64_t seed = 1986);

}  // namespace rc
