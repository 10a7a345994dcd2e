#pragma once
/// \file
/// \brief A stepping render as it was at one step, to go back to that step without
/// replaying from the start.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "order/ray_order.h"
#include "search/cache_strategy.h"
#include "search/cache_tree.h"
#include "search/counters.h"
#include "trace/image_snapshot.h"

namespace rc {

/// Everything of a RenderSession that a step changes: the image so far, the counters, the
/// cache tree with its entries, what the cache strategy learnt beyond them (the blocker
/// lists built), and the order's queues. The scene, the options, the complete search and
/// the sinks are the session's own and not kept. Taken and restored by
/// RenderSession::checkpoint() and restore(); only a stepping session (the GUI's) takes
/// them, never a render's hot path.
struct SessionCheckpoint {
    const void* session = nullptr;  ///< the RenderSession that took it (restored only there)
    std::int64_t steps = 0;      ///< rays traced (RenderSession::steps)
    std::int64_t primaries = 0;  ///< eye rays handed out
    bool done = false;
    Counters counters;
    CacheTree paths;
    ImageSnapshot image;
    std::unique_ptr<RayOrder> order;               ///< a clone, never asked for rays
    std::unique_ptr<StrategyCheckpoint> strategy;  ///< null when the strategy keeps nothing

    /// Bytes it holds, scanlines shared with the checkpoint it was made after excepted.
    std::size_t bytes() const;
};

}  // namespace rc
