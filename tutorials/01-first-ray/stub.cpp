// Tutorial 01: the exercise as shipped, a READ-ONLY copy of exercise.cpp. Do not edit it:
// your work goes in exercise.cpp. The docs quote this file and CI checks that it still fails.
#include "exercise.h"

namespace tutorial {

// [stub]
Answer nearestHit([[maybe_unused]] const rc::Scene& scene, [[maybe_unused]] const Query& q) {
    // TODO: test every object of the scene and keep the nearest hit.
    return Answer{};  // "hits nothing": right for rays into the background only
}
// [stub]

}  // namespace tutorial
