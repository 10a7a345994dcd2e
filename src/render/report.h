#pragma once
/// \file
/// \brief The statistics of a render as JSON.
#include <nlohmann/json.hpp>

#include "analysis/beam_tree.h"
#include "render/render_session.h"

namespace rc {

/// The stats JSON: scene, size, cache, order, seconds, rays by kind, intersection tests,
/// complete searches, cache hits and misses by reason, blocker lists, and the beam tree
/// when `beams` is given.
nlohmann::json statsJson(const RenderSession& session, double seconds, const BeamTreeStats* beams);

/// The counters alone, as the stats JSON has them.
nlohmann::json countersJson(const Counters& n);

}  // namespace rc
