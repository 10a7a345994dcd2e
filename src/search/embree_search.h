#pragma once
/// \file
/// \brief Intel Embree as a complete search, for comparison only (built when CMake finds it).
///
/// Embree computes in single precision, so on a small share of grazing rays it picks
/// another object than the double-precision scan: images made through it may differ
/// slightly, and the exactness guarantee does not cover it.
#include <memory>

#include "search/complete_search.h"

namespace rc {

/// Spheres as Embree's RTC_GEOMETRY_TYPE_SPHERE_POINT, polygons as triangle fans; the
/// origin object is skipped by an intersection filter. Distances are recomputed in double
/// precision on the object Embree found.
class EmbreeSearch final : public CompleteSearch {
public:
    explicit EmbreeSearch(const Scene& scene);
    ~EmbreeSearch() override;
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "embree"; }

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

/// Was RayCache built with Embree?
bool embreeAvailable();

}  // namespace rc
