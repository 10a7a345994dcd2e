#pragma once
/// \file
/// \brief Choosing the complete search: a linear scan, a uniform grid, a bounding volume hierarchy
/// or (for comparison) Embree.
#include <memory>
#include <optional>
#include <string_view>

#include "search/complete_search.h"

namespace rc {

/// Which structure answers complete searches. Any cache sits in front of any of them.
/// Embree is for comparison only: single precision, so not covered by the exactness guarantee.
enum class AccelKind { Linear, Grid, Bvh, Embree };
std::string_view toString(AccelKind k);
std::optional<AccelKind> parseAccelKind(std::string_view s);

/// Makes the complete search of a kind for a scene (which must outlive it).
std::unique_ptr<CompleteSearch> makeCompleteSearch(AccelKind kind, const Scene& scene);

}  // namespace rc
