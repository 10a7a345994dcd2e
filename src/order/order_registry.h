#pragma once
/// \file
/// \brief The ray orders, registered once: each one's name (`--order`), one line that
/// describes it and what makes it. `--order`'s choices, the GUI's and the page's menus and
/// the benchmarks read this list. RayCache's own addition.
#include <functional>
#include <memory>
#include <string>

#include "order/ray_order.h"
#include "scene/registry.h"

namespace rc {

/// One order as the registry holds it.
struct OrderInfo {
    std::string name;         ///< as `--order` takes it, e.g. "bfs"
    std::string description;  ///< one line
    /// makeOrder()'s arguments after the kind.
    std::function<std::unique_ptr<RayOrder>(int width, int rowBegin, int rowEnd, int band, int samples,
                                            bool cheapTests, RayOrder::EyeMaker makeEye)>
        make;
};

/// Every order, in OrderKind's order: the index of an entry is its kind.
const Registry<OrderInfo>& orderRegistry();

}  // namespace rc
