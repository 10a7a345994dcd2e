#pragma once
/// \file
/// \brief The median of a set of measurements (the times of repeated runs).
#include <algorithm>
#include <limits>
#include <vector>

namespace rc {

/// The middle value of `v` once sorted, or the mean of the two middle values when there
/// is an even number of them; NaN for none.
inline double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

}  // namespace rc
