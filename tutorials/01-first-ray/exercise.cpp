// Tutorial 01, your exercise: the complete search. Build and run the check with
//   cmake --build build --target tutorial_01_check_stub && build/tutorials/tutorial_01_check_stub
#include "exercise.h"

namespace tutorial {

// [stub]
rc::Answer nearestHit([[maybe_unused]] const rc::Scene& scene, [[maybe_unused]] const rc::Query& q) {
    // TODO: test every object of the scene and keep the nearest hit.
    return rc::Answer{};  // "hits nothing": right for rays into the background only
}
// [stub]

}  // namespace tutorial
