#pragma once
// The checks' oracle for a least value: golden-section search in long double, independent of
// any function a tutorial grades.
#include <algorithm>
#include <cmath>

namespace tutorial {

/// The least value of `f` over u in [0, 1], for `f` convex (or unimodal) there: 90 steps of
/// golden-section search, the ends included.
template <class F>
long double minimumOnUnit(F f) {
    const long double phi = (std::sqrt(5.0L) - 1.0L) / 2.0L;
    long double lo = 0.0L, hi = 1.0L, x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
    long double f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < 90; ++i) {
        if (f1 <= f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - phi * (hi - lo), f1 = f(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + phi * (hi - lo), f2 = f(x2);
        }
    }
    return std::min({f(0.0L), f(1.0L), f1, f2});
}

}  // namespace tutorial
