#pragma once
// Tutorial 07's oracles (the instructor's: the student edition ships their answers as data,
// tutorials/07-rays-that-hit-nothing/oracle_data.txt, never this code). Included by the
// recording program's oracles.cpp (TUTORIAL_RECORD).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "geometry/safety_cylinder.h"
#include "scene/camera.h"
#include "search/query.h"
#include "oracles.h"

namespace tutorial::instructor {

inline double angleBetween(const rc::Vec3& a, const rc::Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The complete search: the nearest sphere the ray hits, ties to the lower index
inline int nearest(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres) {
    rc::Answer best;
    for (int j = 0; j < int(spheres.size()); ++j) {
        const double t = rc::intersectSphere(ray, spheres[j], rc::Start::Elsewhere);
        if (t < rc::kNoHit && rc::nearer(t, j, best)) best = {j, t};
    }
    return best.object;
}

// The check's oracle for the empty cone. For each sphere, the ray from the apex is turned
// from the axis towards the sphere's centre, in the plane of the two, until it meets the
// sphere: bisection in long double on the angle, a ray meeting the sphere when its distance
// from the centre (a cross product, no cancellation) is at most the radius. The cone opens
// to the least such angle. No formula for the angle of the tangent.
inline double coneAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres) {
    using L = long double;
    struct V {
        L x, y, z;
    };
    auto dot = [](const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    auto cross = [](const V& a, const V& b) {
        return V{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    };
    const L al = std::sqrt(L(axis.x) * axis.x + L(axis.y) * axis.y + L(axis.z) * axis.z);
    const V a{axis.x / al, axis.y / al, axis.z / al};
    L angle = INFINITY;
    for (const rc::Sphere& s : spheres) {
        const V v{L(s.c.x) - apex.x, L(s.c.y) - apex.y, L(s.c.z) - apex.z};
        const L dist = std::sqrt(dot(v, v)), r = s.r;
        if (dist <= r) return -1.0;  // the apex is inside: every ray meets it
        // w: the unit vector in the plane of the axis and the centre, across the axis
        V w{v.x - dot(v, a) * a.x, v.y - dot(v, a) * a.y, v.z - dot(v, a) * a.z};
        L wl = std::sqrt(dot(w, w));
        if (wl < 1e-30L) {  // the centre on the axis's line: any direction across it
            w = std::abs(a.x) < 0.9L ? cross(a, V{1, 0, 0}) : cross(a, V{0, 1, 0});
            wl = std::sqrt(dot(w, w));
        }
        w = {w.x / wl, w.y / wl, w.z / wl};
        auto meets = [&](L theta) {
            const V u{std::cos(theta) * a.x + std::sin(theta) * w.x, std::cos(theta) * a.y + std::sin(theta) * w.y,
                      std::cos(theta) * a.z + std::sin(theta) * w.z};
            const V c = cross(v, u);
            return dot(v, u) > 0 && dot(c, c) <= r * r;
        };
        if (meets(0)) return -1.0;  // the ray along the axis meets it
        const L alpha = std::atan2(std::sqrt(dot(cross(v, a), cross(v, a))), dot(v, a));
        L lo = 0, hi = alpha;  // misses at lo, meets at hi (straight at the centre)
        for (int k = 0; k < 100; ++k) (meets((lo + hi) / 2) ? hi : lo) = (lo + hi) / 2;
        angle = std::min(angle, lo);
    }
    return double(angle);
}

// 4-connected pieces of pixels whose rays hit nothing: the beams of empty eye rays, by
// brute force as tutorials 04 and 05 count theirs (every such pixel starts with its own
// label; sweep after sweep each takes the least label of its empty 4-neighbours, until none
// changes; each label left is one beam)
inline long emptyBeams(int width, int height, const std::vector<int>& truth) {
    std::vector<int> label(truth.size());
    for (int p = 0; p < width * height; ++p) label[p] = p;
    for (bool changed = true; changed;) {
        changed = false;
        for (int p = 0; p < width * height; ++p) {
            if (truth[p] >= 0) continue;
            const int x = p % width, y = p / width;
            for (const int q : {x > 0 ? p - 1 : -1, x + 1 < width ? p + 1 : -1, y > 0 ? p - width : -1,
                                y + 1 < height ? p + width : -1})
                if (q >= 0 && truth[q] < 0 && label[q] < label[p]) label[p] = label[q], changed = true;
        }
    }
    long beams = 0;
    for (int p = 0; p < width * height; ++p) beams += truth[p] < 0 && label[p] == p;
    return beams;
}

// The complete search's answer for every eye ray (tutorial::eyeHits)
inline std::vector<double> eyeHits(const std::vector<rc::Sphere>& spheres, const rc::Camera& eye, int width, int height) {
    const rc::RayGenerator camera(eye, width, height);
    std::vector<double> out(std::size_t(width) * std::size_t(height));
    for (int p = 0; p < width * height; ++p) out[std::size_t(p)] = nearest(camera.primary(p % width, p / width), spheres);
    return out;
}

// The cylinder of safety's row (tutorial::cylinderRow), counted as the check's drive()
// counts a cache: {cost, emptyCost, searchesPerBeam, testsPerAnswer, searches, tests,
// afterEmptyAnswered, afterEmpty}. The cylinder for a ray that hits nothing is the segment
// from the eye to where the ray leaves the spheres' bounding sphere (its nearest point to
// the centre if it misses it), as thick as the gap to the nearest sphere; a later ray is
// answered "nothing" when that segment's end stays inside it. Its lookups test no sphere;
// the bounding sphere costs 3n tests (each sphere read once for the centre, and once for
// its centre and once for its radius for the radius: as the check counted it when it ran
// this cache itself), each new cylinder n.
inline std::vector<double> cylinderRow(const std::vector<rc::Sphere>& spheres, const rc::Camera& eye, int width,
                                       int height) {
    const rc::RayGenerator camera(eye, width, height);
    const int n = int(spheres.size());
    const rc::Vec3 from = eye.from;
    rc::Sphere bound{rc::Vec3{0.0}, 0.0};
    for (const rc::Sphere& s : spheres) bound.c += s.c / double(n);
    for (const rc::Sphere& s : spheres) bound.r = std::max(bound.r, glm::length(s.c - bound.c) + s.r);
    auto segmentEnd = [&](const rc::Vec3& d) {
        const rc::Ray ray{from, d};
        const rc::SphereRoots roots = rc::sphereRootsStable(ray, bound);
        return ray.at(roots.hit && roots.t1 > 0.0 ? roots.t1 : std::max(0.0, glm::dot(bound.c - from, d)));
    };
    rc::Vec3 end{0.0};
    double radius = -1.0;
    const long setupTests = 3L * n;
    long searches = 0, searchedTests = 0, afterEmpty = 0, afterEmptyAnswered = 0;
    double cost = double(setupTests) / double(n), emptyCost = 0.0;
    std::vector<int> truth(std::size_t(width) * std::size_t(height));
    for (int p = 0; p < width * height; ++p) truth[std::size_t(p)] = nearest(camera.primary(p % width, p / width), spheres);
    for (int p = 0; p < width * height; ++p) {
        const rc::Vec3 d = camera.primary(p % width, p / width).d;
        const int hit = truth[std::size_t(p)];
        const bool after = hit >= 0 && p % width > 0 && truth[std::size_t(p) - 1] < 0;
        afterEmpty += after;
        double rayCost = 0.0;
        if (radius > 0.0 && rc::segmentDistance(segmentEnd(d), from, end) <= radius) {
            if (hit >= 0) throw std::logic_error("the cylinder of safety answered nothing for a ray that hits a sphere");
            afterEmptyAnswered += after;
        } else {
            ++searches;
            rayCost += 1.0;
            if (hit < 0) {
                end = segmentEnd(d);
                radius = rc::kNoHit;
                for (const rc::Sphere& s : spheres) radius = std::min(radius, rc::segmentDistance(s.c, from, end) - s.r);
                radius *= 1.0 - 1e-12;
                searchedTests += n;
                rayCost += double(n) / double(n);
            }
        }
        cost += rayCost;
        if (hit < 0) emptyCost += rayCost;
    }
    const long beams = emptyBeams(width, height, truth);
    return {cost, emptyCost, beams ? emptyCost / double(beams) : 0.0, 0.0, double(searches),
            double(setupTests + searchedTests), double(afterEmptyAnswered), double(afterEmpty)};
}

// The yardstick of the challenge (tutorial::oneCone): {searches, emptySearches, cost}
inline std::vector<double> oneCone(const std::vector<rc::Sphere>& spheres, const rc::Camera& eye, int width, int height) {
    const rc::RayGenerator camera(eye, width, height);
    OneCone out;
    rc::Vec3 axis{0.0};
    double angle = -1.0;
    for (int p = 0; p < width * height; ++p) {
        const rc::Ray ray = camera.primary(p % width, p / width);
        if (angle > 0.0 && angleBetween(axis, ray.d) < angle * (1.0 - 1e-9)) continue;
        ++out.searches;
        out.cost += 1.0;
        if (nearest(ray, spheres) >= 0) continue;
        ++out.emptySearches;
        out.cost += 1.0;
        axis = ray.d;
        angle = coneAngle(eye.from, ray.d, spheres);
    }
    return {double(out.searches), double(out.emptySearches), out.cost};
}

}  // namespace tutorial::instructor
