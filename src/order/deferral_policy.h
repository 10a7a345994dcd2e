#pragma once
/// \file
/// \brief Breadth-first order's deferral policy: which caches are asked cheaply first.
#include "search/cache_strategy.h"

namespace rc {

// [deferral-policy]
/// Should breadth-first order ask `cache` cheaply first, and defer a ray whose cheap lookup
/// fails to seed a later region? That saves a complete search only where one costs more
/// than asking twice; otherwise every ray is asked fully when its turn comes. `cheapSearch`:
/// the complete search makes a few tests rather than one per object (CompleteSearch::cheap).
/// - No cache: never (every lookup searches).
/// - The cylinder cache and the paper's blocker cache: always.
/// - Blocker+ only in front of the linear scan: in front of a grid or a hierarchy, deferring
///   a ray costs a second lookup and a place in the queue, more than the search it saves.
/// - Blocker+dir: never. Where its misses test direction lists (the linear scan) a deferral
///   costs more than the few tests of a list; elsewhere it is blocker+ in front of a cheap
///   search.
bool defersMisses(CacheKind cache, bool cheapSearch);
// [deferral-policy]

}  // namespace rc
