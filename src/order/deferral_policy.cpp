#include "order/deferral_policy.h"

namespace rc {

bool defersMisses(CacheKind cache, bool cheapSearch) {
    switch (cache) {
        case CacheKind::None: return false;
        case CacheKind::Cylinder:
        case CacheKind::Blocker: return true;
        case CacheKind::BlockerPlus: return !cheapSearch;
        case CacheKind::BlockerDirections: return false;
    }
    return false;
}

}  // namespace rc
