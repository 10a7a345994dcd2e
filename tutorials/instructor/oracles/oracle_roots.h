#pragma once
// An independent oracle for the checks: the roots of |o + t d - c|^2 = r^2 found by
// bisection in long double and polished by Newton's method in __float128, never by the
// quadratic formula (stable or not). Accurate to far below a double's rounding on every
// case the checks draw; slow, which a check can afford.
#include <cmath>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {

struct OracleRoots {
    bool hit = false;
    long double t0 = 0.0L, t1 = 0.0L;
};

namespace oracle_detail {
using Quad = __float128;
// g(t) = |f + t d|^2 - r^2 with f = o - c, each coordinate formed before squaring
template <class T>
T g(const rc::Ray& ray, const rc::Sphere& s, T t) {
    T sum = 0;
    for (int i = 0; i < 3; ++i) {
        const T x = (T(ray.o[i]) - T(s.c[i])) + t * T(ray.d[i]);
        sum += x * x;
    }
    return sum - T(s.r) * T(s.r);
}
template <class T>
T dg(const rc::Ray& ray, const rc::Sphere& s, T t) {
    T sum = 0;
    for (int i = 0; i < 3; ++i) sum += T(2) * T(ray.d[i]) * ((T(ray.o[i]) - T(s.c[i])) + t * T(ray.d[i]));
    return sum;
}
// The root of g between lo (sign of g: `loSign`) and hi
inline long double bisect(const rc::Ray& ray, const rc::Sphere& s, long double lo, long double hi, bool loPositive) {
    for (int i = 0; i < 200 && lo < hi; ++i) {
        const long double mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi) break;
        if ((g<long double>(ray, s, mid) > 0) == loPositive) lo = mid; else hi = mid;
    }
    Quad t = Quad(lo + (hi - lo) / 2);
    for (int i = 0; i < 3; ++i) {  // Newton in quad precision from a bracketed start
        const Quad d = dg<Quad>(ray, s, t);
        if (d == 0) break;
        t -= g<Quad>(ray, s, t) / d;
    }
    return (long double)t;
}
}  // namespace oracle_detail

/// Both roots of the ray's equation with sphere `s`, or hit = false when the ray's line
/// misses it (the least of |o + t d - c|^2 - r^2 is positive).
inline OracleRoots oracleRoots(const rc::Ray& ray, const rc::Sphere& s) {
    using namespace oracle_detail;
    Quad fd = 0, dd = 0;
    for (int i = 0; i < 3; ++i) {
        fd += (Quad(ray.o[i]) - Quad(s.c[i])) * Quad(ray.d[i]);
        dd += Quad(ray.d[i]) * Quad(ray.d[i]);
    }
    const Quad tm = -fd / dd;  // the nearest approach to the centre
    if (g<Quad>(ray, s, tm) > 0) return {};
    const long double m = (long double)tm;
    const long double reach = 2.0L * (long double)s.r + 1.0L;  // |d| ~ 1: g > 0 this far from tm
    return {true, bisect(ray, s, m - reach, m, true), bisect(ray, s, m, m + reach, false)};
}

}  // namespace tutorial
