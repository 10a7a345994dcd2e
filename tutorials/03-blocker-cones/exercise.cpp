// Tutorial 03, your exercise: the distance to the hull of two spheres. Build and run:
//   cmake --build build --target tutorial_03_check_stub && build/tutorials/tutorial_03_check_stub
#include <glm/geometric.hpp>

#include "exercise.h"

namespace tutorial {

// [stub]
double hullDistance(const rc::Vec3& p, const rc::Sphere& a, [[maybe_unused]] const rc::Sphere& b) {
    // TODO: the hull is both spheres and the cone between them; this sees sphere a only.
    return glm::length(p - a.c) - a.r;
}
// [stub]

}  // namespace tutorial
