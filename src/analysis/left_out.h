#pragma once
/// \file
/// \brief What a scene does not need, and so is left out of its renders.
///
/// Shading spawns no shadow ray without lights (or toward a light that adds nothing), no
/// reflection ray where Ks is 0, no refraction ray where T is 0, and nothing beyond the
/// eye ray at depth 1; the blocker cache builds a list only for a pair of sites a ray
/// actually travels between, and an interior list (a sphere with itself) only for rays
/// inside a transparent sphere. leftOut() says which of these a scene leaves out.
#include <string>
#include <vector>

#include "scene/scene.h"
#include "trace/shading.h"

namespace rc {

class BlockerLists;

/// What renders of `scene` leave out, one line each such as "shadow rays: no lights".
/// With `lists`, also how many blocker lists were never built.
std::vector<std::string> leftOut(const Scene& scene, const ShadingOptions& shading = {},
                                 const BlockerLists* lists = nullptr);

}  // namespace rc
