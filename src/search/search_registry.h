#pragma once
/// \file
/// \brief The complete searches, registered once: each one's name (`--accel`), one line that
/// describes it and what makes it. `--accel`'s choices, the GUI's and the page's menus and
/// `bench` read this list. RayCache's own addition.
#include <functional>
#include <memory>
#include <string>

#include "scene/registry.h"
#include "search/accelerator.h"

namespace rc {

/// One complete search as the registry holds it.
struct SearchInfo {
    std::string name;         ///< as `--accel` takes it, e.g. "bvh"
    std::string description;  ///< one line
    std::function<std::unique_ptr<CompleteSearch>(const Scene&)> make;
    /// For comparison only (not exact, so not in the menus nor the web page): Embree.
    bool comparisonOnly = false;
};

/// Every complete search, in AccelKind's order: the index of an entry is its kind.
const Registry<SearchInfo>& searchRegistry();

}  // namespace rc
