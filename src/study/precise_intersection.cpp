#include "study/precise_intersection.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include <glm/geometric.hpp>

#include "scene/random.h"

namespace rc {

namespace {

using LD = long double;
constexpr LD kNoHitL = std::numeric_limits<LD>::infinity();

template <class T>
struct V3 {
    T x, y, z;
};
template <class T>
V3<T> conv(const Vec3& v) {
    return {T(v.x), T(v.y), T(v.z)};
}
template <class T>
V3<T> sub(const V3<T>& a, const V3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Roots of |o + t d - c|^2 = r^2 with the stable discriminant: for any |d| (the
// reference), or taking |d| = 1 as intersection.cpp does (`unit`)
template <class T>
bool stableRoots(const V3<T>& o, const V3<T>& d, const V3<T>& c, T r, T& t0, T& t1, bool unit = false) {
    // BEGIN SOLUTION 06
    const V3<T> f = sub(o, c);
    const T a = unit ? T(1) : dot(d, d);
    const T b = dot(f, d);
    const T k = b / a;
    const V3<T> l{f.x - k * d.x, f.y - k * d.y, f.z - k * d.z};
    const T disc = r * r - dot(l, l);
    if (disc < T(0)) return false;
    const T root = std::sqrt(a * disc);
    const T q = b > T(0) ? -b - root : -b + root;
    const T cc = dot(f, f) - r * r;
    t0 = q != T(0) ? cc / q : T(0);
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
    // END SOLUTION
    // BEGIN STUB
    // // Tutorial 06's answer in any precision: not in the student edition while 06 is open
    // (void)o, (void)d, (void)c, (void)r, (void)t0, (void)t1, (void)unit;
    // return false;
    // END STUB
}

// The textbook roots -b +- sqrt(b^2 - c) for a unit d
template <class T>
bool textbookRoots(const V3<T>& o, const V3<T>& d, const V3<T>& c, T r, T& t0, T& t1) {
    const V3<T> f = sub(o, c);
    const T b = dot(f, d);
    const T cc = dot(f, f) - r * r;
    const T disc = b * b - cc;
    if (disc < T(0)) return false;
    const T root = std::sqrt(disc);
    t0 = -b - root;
    t1 = -b + root;
    return true;
}

template <class T>
T nearestPositive(bool hit, T t0, T t1) {
    if (!hit) return std::numeric_limits<T>::infinity();
    if (t0 > T(0)) return t0;
    return t1 > T(0) ? t1 : std::numeric_limits<T>::infinity();
}

struct Probe {
    Ray ray;
    Sphere sphere;
};

// Points uniformly on a disk of radius `r` around `c`, perpendicular to `n`
Vec3 diskPoint(Random& g, const Vec3& c, const Vec3& n, double r) {
    Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(n, a)), v = glm::cross(n, u);
    const double rho = r * std::sqrt(g.unit()), phi = 2.0 * std::numbers::pi * g.unit();
    return c + rho * (std::cos(phi) * u + std::sin(phi) * v);
}

Vec3 randomDirection(Random& g) {
    const double z = 2 * g.unit() - 1, phi = 2.0 * std::numbers::pi * g.unit();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3(s * std::cos(phi), s * std::sin(phi), z);
}

// Rays from `dist` away aimed at a disk 1.1 times the sphere's radius
std::vector<Probe> aimed(Random& g, const Sphere& s, double dist, int n) {
    std::vector<Probe> out;
    for (int i = 0; i < n; ++i) {
        const Vec3 from = s.c + dist * randomDirection(g);
        const Vec3 to = diskPoint(g, s.c, glm::normalize(s.c - from), 1.1 * s.r);
        out.push_back({{from, glm::normalize(to - from)}, s});
    }
    return out;
}

std::vector<Probe> makeCase(int which, Random& g, int n) {
    switch (which) {
        case 0: return aimed(g, {Vec3(0.3, -0.2, 0.1), 1.0}, 5.0, n);
        case 1: return aimed(g, {Vec3(0.0), 1.0}, 1e6, n);
        case 2: return aimed(g, {Vec3(0.0), 1e-3}, 1e6, n);
        case 3: return aimed(g, {Vec3(0.1, 0.2, 0.3), 1e-6}, 1.0, n);
        case 4: return aimed(g, {Vec3(1e7, 1e7, 1e7), 1.0}, 5.0, n);
        case 5: {
            // Perpendicular offset r (1 - 10^-k), k from 3 to 12: rays graze the silhouette
            std::vector<Probe> out;
            const Sphere s{Vec3(0.0), 1.0};
            for (int i = 0; i < n; ++i) {
                const Vec3 d = randomDirection(g);
                const Vec3 side = glm::normalize(glm::cross(d, randomDirection(g)));
                const double off = s.r * (1.0 - std::pow(10.0, -3.0 - 9.0 * g.unit()));
                out.push_back({{s.c + off * side - 10.0 * d, d}, s});
            }
            return out;
        }
        case 6: {
            // Origins 1e-6 to 1e-2 above a sphere of radius 1e6, heading down into it
            std::vector<Probe> out;
            const Sphere s{Vec3(0.0, -1e6, 0.0), 1e6};
            for (int i = 0; i < n; ++i) {
                const double h = std::pow(10.0, -6.0 + 4.0 * g.unit());
                const Vec3 o(20.0 * g.unit() - 10.0, h, 20.0 * g.unit() - 10.0);
                Vec3 d = randomDirection(g);
                if (d.y > 0) d.y = -d.y;
                out.push_back({{o, d}, s});
            }
            return out;
        }
    }
    return {};
}

template <class T, bool Stable>
T evaluate(const Probe& p) {
    if constexpr (std::is_same_v<T, double>) {
        // The routines the renderer uses
        const SphereRoots r = Stable ? sphereRootsStable(p.ray, p.sphere) : sphereRootsTextbook(p.ray, p.sphere);
        return nearestPositive(r.hit, r.t0, r.t1);
    }
    const V3<T> o = conv<T>(p.ray.o), d = conv<T>(p.ray.d), c = conv<T>(p.sphere.c);
    T t0, t1;
    const bool hit = Stable ? stableRoots(o, d, c, T(p.sphere.r), t0, t1, true) : textbookRoots(o, d, c, T(p.sphere.r), t0, t1);
    return nearestPositive(hit, t0, t1);
}

template <class T, bool Stable>
IntersectionRow measure(const std::vector<Probe>& probes, const std::vector<LD>& ref) {
    IntersectionRow row;
    row.rays = std::int64_t(probes.size());
    std::vector<double> errors;
    for (std::size_t i = 0; i < probes.size(); ++i) {
        const T t = evaluate<T, Stable>(probes[i]);
        const bool hit = std::isfinite(double(t)), refHit = std::isfinite(double(ref[i]));
        if (hit != refHit) {
            ++row.wrongHits;
            continue;
        }
        if (hit) errors.push_back(double(std::abs(LD(t) - ref[i]) / std::abs(ref[i])));
    }
    if (!errors.empty()) {
        std::sort(errors.begin(), errors.end());
        row.maxRelError = errors.back();
        row.medianRelError = errors[errors.size() / 2];
    }
    // Time: repeat the batch until it has run 20 ms
    using Clock = std::chrono::steady_clock;
    volatile double sink = 0;
    std::int64_t tests = 0;
    const auto start = Clock::now();
    double seconds = 0;
    do {
        double sum = 0;
        for (const Probe& p : probes) {
            const T t = evaluate<T, Stable>(p);
            if (t < T(1e30)) sum += double(t);
        }
        sink = sink + sum;
        tests += std::int64_t(probes.size());
        seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } while (seconds < 0.02);
    row.nsPerTest = 1e9 * seconds / double(tests);
    return row;
}

}  // namespace

long double preciseSphereHit(const Ray& ray, const Sphere& s, Start start) {
    if (start == Start::Leaving) return kNoHitL;
    LD t0, t1;
    if (!stableRoots(conv<LD>(ray.o), conv<LD>(ray.d), conv<LD>(s.c), LD(s.r), t0, t1)) return kNoHitL;
    if (start == Start::Entering) return t1 > 0 ? t1 : kNoHitL;
    return nearestPositive(true, t0, t1);
}

long double precisePolygonHit(const Ray& ray, const Polygon& poly, bool fromThis) {
    if (fromThis) return kNoHitL;
    // Newell's normal and the mean offset, in long double
    const std::size_t n = poly.vertices.size();
    V3<LD> nl{0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
        const V3<LD> a = conv<LD>(poly.vertices[i]), b = conv<LD>(poly.vertices[(i + 1) % n]);
        nl.x += (a.y - b.y) * (a.z + b.z);
        nl.y += (a.z - b.z) * (a.x + b.x);
        nl.z += (a.x - b.x) * (a.y + b.y);
    }
    LD offset = 0;
    for (const Vec3& v : poly.vertices) offset += dot(nl, conv<LD>(v));
    offset /= LD(n);
    const V3<LD> o = conv<LD>(ray.o), d = conv<LD>(ray.d);
    const LD denom = dot(nl, d);
    if (denom == 0) return kNoHitL;
    const LD t = (offset - dot(nl, o)) / denom;
    if (!(t > 0)) return kNoHitL;
    const V3<LD> p{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
    // Inside a simple polygon, convex or not: an odd number of edges crosses the half-line
    // from p along one in-plane axis (the plane seen along its largest normal component)
    const LD ax = nl.x < 0 ? -nl.x : nl.x, ay = nl.y < 0 ? -nl.y : nl.y, az = nl.z < 0 ? -nl.z : nl.z;
    const int drop = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    auto uv = [&](const V3<LD>& v, LD& u, LD& w) {
        const LD c[3] = {v.x, v.y, v.z};
        u = c[(drop + 1) % 3];
        w = c[(drop + 2) % 3];
    };
    LD pu, pv;
    uv(p, pu, pv);
    bool inside = false;
    for (std::size_t i = 0; i < n; ++i) {
        LD au, av, bu, bv;
        uv(conv<LD>(poly.vertices[i]), au, av);
        uv(conv<LD>(poly.vertices[(i + 1) % n]), bu, bv);
        if ((av > pv) != (bv > pv) && pu < au + (pv - av) * (bu - au) / (bv - av)) inside = !inside;
    }
    return inside ? t : kNoHitL;
}

long double preciseHit(const Scene& scene, const Ray& ray, int id, const RayOrigin& origin) {
    const Object& o = scene.objects[id];
    const bool self = origin.object == id;
    if (o.shape == Shape::Polygon) return precisePolygonHit(ray, scene.polygons[o.index], self);
    // Cones are not studied in extended precision: their double answer stands in
    if (o.shape == Shape::Cone) return intersectTruncatedCone(ray, scene.cones[o.index], self);
    const Start start = !self ? Start::Elsewhere : origin.inside ? Start::Entering : Start::Leaving;
    return preciseSphereHit(ray, scene.spheres[o.index], start);
}

std::vector<std::pair<std::string, std::string>> intersectionCases() {
    return {{"control: r=1 at 5", "an ordinary sphere, an ordinary distance"},
            {"r=1 sphere 1e6 away", "the camera 1e6 away: b*b and c are 1e12, their difference 1"},
            {"r=1e-3 sphere 1e6 away", "a grain of dust seen from far: b*b - c is 1e-6 out of 1e12"},
            {"r=1e-6 sphere at 1", "a tiny sphere: b*b - c is 1e-12 out of 1"},
            {"r=1 at 1e7 offset", "every coordinate 1e7: a float cannot even hold the positions"},
            {"grazing r(1-1e-k)", "rays passing 1e-3 to 1e-12 of the radius inside the silhouette"},
            {"1e-6..1e-2 above r=1e6", "origins just above a huge sphere: the near root is a small "
                                        "difference of large numbers"}};
}

std::vector<IntersectionRow> compareIntersections(int raysPerCase, std::uint64_t seed) {
    std::vector<IntersectionRow> rows;
    const auto cases = intersectionCases();
    for (int c = 0; c < int(cases.size()); ++c) {
        Random g(seed + 7919 * std::uint64_t(c));
        const std::vector<Probe> probes = makeCase(c, g, raysPerCase);
        std::vector<LD> ref;
        for (const Probe& p : probes) ref.push_back(preciseSphereHit(p.ray, p.sphere, Start::Elsewhere));
        auto add = [&](IntersectionRow r, const char* formula, const char* precision) {
            r.stiffCase = cases[c].first;
            r.formula = formula;
            r.precision = precision;
            rows.push_back(r);
        };
        add(measure<float, false>(probes, ref), "textbook", "float");
        add(measure<float, true>(probes, ref), "stable", "float");
        add(measure<double, false>(probes, ref), "textbook", "double");
        add(measure<double, true>(probes, ref), "stable", "double");
        IntersectionRow r = measure<LD, true>(probes, ref);
        add(r, "stable", "long double");
    }
    return rows;
}

}  // namespace rc
