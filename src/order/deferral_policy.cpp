#include "order/deferral_policy.h"
#include "search/cache_registry.h"

namespace rc {

bool defersMisses(CacheKind cache, bool cheapSearch) {
    // Each cache says which rule it follows where it is registered (search/cache_registry.cpp)
    switch (cacheInfo(cache).deferral) {
        case Deferral::Never: return false;
        case Deferral::Always: return true;
        case Deferral::UnlessCheapSearch: return !cheapSearch;
    }
    return false;
}

}  // namespace rc
