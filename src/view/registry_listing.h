#pragma once
/// \file
/// \brief Every registry's entries as JSON, for `raycache list` and the web page's menus (one
/// listing, read by both). RayCache's own addition.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace rc {

/// What the registry `what` holds ("caches", "orders", "searches", "overlays" or "scenes"):
/// [{name, description, ...}] in menu order. Caches add `blocker_lists` and `in_sweeps`,
/// searches `comparison_only`, overlays `aliases` and `in_page`, scenes `sizes` (built-in
/// scenes whose name ends in ":N").
/// \throws std::invalid_argument for any other `what`.
nlohmann::json registryListing(std::string_view what);

}  // namespace rc
