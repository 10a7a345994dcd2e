#pragma once
/// \file
/// \brief The statistics of a render as JSON.
#include <nlohmann/json.hpp>

#include "analysis/beam_tree.h"
#include "render/render_session.h"

namespace rc {

/// What a finished render (one session, or several threads' sessions) reports.
struct RenderSummary {
    std::string scene;
    RenderOptions options;  ///< with the image size resolved
    Counters counters;
    std::size_t queuePeak = 0;
    std::int64_t regions = 0;
    int paths = 0;  ///< ray-tree paths met
    int threads = 1;
    std::vector<std::string> leftOut;  ///< what the scene did not need (render/left_out.h)
};

/// The summary of one session.
RenderSummary summarize(const RenderSession& session);

/// The stats JSON: scene, size, cache, order, seconds, rays by kind, intersection tests,
/// complete searches, cache hits and misses by reason, blocker lists, and the beam tree
/// when `beams` is given.
nlohmann::json statsJson(const RenderSummary& summary, double seconds, const BeamTreeStats* beams);

/// The counters alone, as the stats JSON has them.
nlohmann::json countersJson(const Counters& n);

}  // namespace rc
