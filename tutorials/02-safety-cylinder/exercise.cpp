// Tutorial 02, your exercise: distance from a point to a segment. Build and run the check:
//   cmake --build build --target tutorial_02_check_stub && build/tutorials/tutorial_02_check_stub
#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

// [stub]
double segmentDistance(const rc::Vec3& p, const rc::Vec3& a, [[maybe_unused]] const rc::Vec3& b) {
    // TODO: the distance to the nearest point of the segment, not just to its start.
    return glm::length(p - a);
}
// [stub]

}  // namespace tutorial
