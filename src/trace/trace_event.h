#pragma once
/// \file
/// \brief What one traced ray reports: the statistics, the GUI and the beam tree listen.
#include <cstdint>

#include "search/cache_strategy.h"
#include "trace/ray_task.h"

namespace rc {

/// One step of a render. `deferred` events are cheap tests that failed in breadth-first
/// order: the ray waits and is traced later, so it emits a second event then.
struct TraceEvent {
    std::int64_t step = 0;  ///< rays committed before this one
    RayTask task;
    Lookup lookup;          ///< answer, decision, miss reason, whether it searched
    int tests = 0;          ///< ray-object tests this lookup made
    bool deferred = false;
};

/// Receives trace events.
class TraceSink {
public:
    virtual ~TraceSink() = default;
    virtual void onEvent(const TraceEvent& e) = 0;
};

}  // namespace rc
