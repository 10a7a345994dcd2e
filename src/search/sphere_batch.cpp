#include "search/sphere_batch.h"

namespace rc {

void SphereBatch::add(const Scene& scene, int id) {
    const Object& o = scene.objects[id];
    const bool sphere = o.shape == Shape::Sphere;
    // The very sphere Scene::intersect() tests, so both compute the same discriminant
    const Sphere s = sphere ? scene.spheres[o.index] : o.bound;
    ids_.push_back(id);
    x_.push_back(s.c.x);
    y_.push_back(s.c.y);
    z_.push_back(s.c.z);
    radius2_.push_back(sphere ? s.r * s.r : -1.0);
}

}  // namespace rc
