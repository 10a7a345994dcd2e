#pragma once
/// \file
/// \brief The complete search: what every cache falls back on when it misses.
#include <memory>
#include <string>

#include "search/query.h"

namespace rc {

/// Finds the nearest hit over the whole scene. Implementations (a linear scan now, a grid
/// or BVH later) must return exactly what the linear scan returns, ties included.
class CompleteSearch {
public:
    virtual ~CompleteSearch() = default;
    /// The nearest hit of `q`, counting every ray-object test in `n`.
    virtual Answer nearest(const Query& q, Counters& n) const = 0;
    virtual std::string name() const = 0;
};

/// Tests every object in the scene: the paper's "standard ray-tracing algorithm".
class LinearSearch final : public CompleteSearch {
public:
    explicit LinearSearch(const Scene& scene) : scene_(scene) {}
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "linear"; }

private:
    const Scene& scene_;
};

}  // namespace rc
