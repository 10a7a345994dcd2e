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

#include "render/render_session.h"

namespace rc {

/// What renders of `scene` leave out, one line each such as "shadow rays: no lights".
/// With `options`, also what its depth leaves out; with `counters` of a blocker-cache
/// render, how many of the possible blocker lists were never built.
std::vector<std::string> leftOut(const Scene& scene, const RenderOptions* options = nullptr,
                                 const Counters* counters = nullptr);

}  // namespace rc
