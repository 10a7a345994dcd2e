// Tutorial 03: the exercise as shipped, a READ-ONLY copy of exercise.cpp. Do not edit it:
// your work goes in exercise.cpp. The docs quote this file and CI checks that it still fails.
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
