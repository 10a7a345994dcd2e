#include "search/counters.h"

#include <algorithm>

namespace rc {

std::string_view toString(Decision d) {
    switch (d) {
        case Decision::Uncached: return "uncached";
        case Decision::Hit: return "hit";
        case Decision::Miss: return "miss";
    }
    return "?";
}

std::string_view toString(MissReason r) {
    switch (r) {
        case MissReason::None: return "none";
        case MissReason::Cold: return "cold";
        case MissReason::Flushed: return "flushed";
        case MissReason::OriginChanged: return "origin_changed";
        case MissReason::TargetMissed: return "target_missed";
        case MissReason::BlockerHit: return "blocker_hit";
        case MissReason::LeftCylinder: return "left_cylinder";
        case MissReason::LeftCone: return "left_cone";
    }
    return "?";
}

Counters& Counters::operator+=(const Counters& o) {
    for (int i = 0; i < kRayKinds; ++i) rays[i] += o.rays[i];
    primaryHits += o.primaryHits;
    intersectionTests += o.intersectionTests;
    completeSearches += o.completeSearches;
    cylinderTests += o.cylinderTests;
    coneTests += o.coneTests;
    hits += o.hits;
    misses += o.misses;
    for (int i = 0; i < kMissReasons; ++i) missReasons[i] += o.missReasons[i];
    deferrals += o.deferrals;
    verifyDisagreements += o.verifyDisagreements;
    blockerListsBuilt += o.blockerListsBuilt;
    blockerListEntries += o.blockerListEntries;
    blockerListMax = std::max(blockerListMax, o.blockerListMax);
    hullTests += o.hullTests;
    cylindersBuilt += o.cylindersBuilt;
    conesBuilt += o.conesBuilt;
    cylindersRuledOut += o.cylindersRuledOut;
    steppedAside += o.steppedAside;
    directionSearches += o.directionSearches;
    directionListsBuilt += o.directionListsBuilt;
    directionListEntries += o.directionListEntries;
    return *this;
}

}  // namespace rc
