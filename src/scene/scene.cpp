#include "scene/scene.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"

namespace rc {

int Scene::addSphere(Sphere s, int mat) {
    spheres.push_back(s);
    objects.push_back({Shape::Sphere, int(spheres.size()) - 1, mat, s});
    return int(objects.size()) - 1;
}

int Scene::addPolygon(Polygon p, int mat) {
    const Sphere b = p.bound;
    polygons.push_back(std::move(p));
    objects.push_back({Shape::Polygon, int(polygons.size()) - 1, mat, b});
    return int(objects.size()) - 1;
}

int Scene::addCone(const TruncatedCone& c, int mat) {
    cones.push_back(c);
    objects.push_back({Shape::Cone, int(cones.size()) - 1, mat, boundingSphere(c)});
    return int(objects.size()) - 1;
}

void Scene::finalize() {
    if (objects.empty()) {
        bound = {Vec3(0.0), 0.0};
        return;
    }
    Vec3 lo = objects.front().bound.c, hi = lo;
    for (const Object& o : objects) {
        lo = glm::min(lo, o.bound.c - Vec3(o.bound.r));
        hi = glm::max(hi, o.bound.c + Vec3(o.bound.r));
    }
    bound.c = 0.5 * (lo + hi);
    bound.r = 0.0;
    for (const Object& o : objects) bound.r = std::max(bound.r, glm::length(o.bound.c - bound.c) + o.bound.r);
    bound.r *= 1.0 + 1e-9;
}

double Scene::intersect(const Ray& ray, int id, const RayOrigin& origin) const {
    const Object& o = objects[id];
    const bool self = origin.object == id;
    if (o.shape == Shape::Polygon) return intersectPolygon(ray, polygons[o.index], self);
    if (o.shape == Shape::Cone) return intersectTruncatedCone(ray, cones[o.index], self);
    const Start start = !self ? Start::Elsewhere : origin.inside ? Start::Entering : Start::Leaving;
    return intersectSphere(ray, spheres[o.index], start);
}

Vec3 Scene::normal(int id, const Vec3& p) const {
    const Object& o = objects[id];
    if (o.shape == Shape::Polygon) return polygonNormal(polygons[o.index], p);
    if (o.shape == Shape::Cone) return truncatedConeNormal(cones[o.index], p);
    const Sphere& s = spheres[o.index];
    return (p - s.c) / s.r;
}

double Scene::extent() const {
    double e = glm::length(bound.c) + bound.r + glm::length(camera.from);
    for (const Light& l : lights) e = std::max(e, glm::length(l.position));
    return e;
}

bool Scene::has(Shape s) const {
    return std::any_of(objects.begin(), objects.end(), [&](const Object& o) { return o.shape == s; });
}

bool Scene::hasTransparency() const {
    return std::any_of(objects.begin(), objects.end(),
                       [&](const Object& o) { return materials[o.material].kt > 0.0; });
}

SceneError::SceneError(std::string f, int l, int c, std::string m)
    : std::runtime_error(f + ":" + std::to_string(l) + ":" + std::to_string(c) + ": " + m),
      file(std::move(f)), line(l), column(c), message(std::move(m)) {}

std::shared_ptr<const Scene> withLightRadius(std::shared_ptr<const Scene> scene, double radius) {
    if (!(radius > 0.0)) return scene;
    bool same = true;
    for (const Light& l : scene->lights) same = same && l.radius == radius;
    if (same) return scene;
    auto copy = std::make_shared<Scene>(*scene);
    for (Light& l : copy->lights) l.radius = radius;
    return copy;
}

}  // namespace rc
