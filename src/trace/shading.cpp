#include "trace/shading.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rc {

namespace {
double maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
}  // namespace

RayTask primaryTask(const Ray& ray, int pixel) {
    RayTask t;
    t.query.ray = ray;
    t.query.kind = RayKind::Primary;
    t.pixel = pixel;
    return t;
}

void shade(const Scene& scene, const RayTask& task, const Answer& hit, const ShadingOptions& opt,
           CacheTree& paths, ImageAccumulator& image, std::vector<RayTask>& children) {
    const Query& q = task.query;
    // [shade-leaves]
    // A shadow ray that reaches its light brings the light it was carrying
    if (q.kind == RayKind::Shadow) {
        if (hit.object < 0) image.add(task.pixel, task.unblocked);
        return;
    }
    // A ray that hits nothing sees the background
    if (hit.object < 0) {
        image.add(task.pixel, task.weight * scene.background);
        return;
    }
    // [shade-leaves]
    const Object& obj = scene.objects[hit.object];
    const Material& m = scene.materials[obj.material];
    const Vec3 p = q.ray.at(hit.t);
    const Vec3 outward = scene.normal(hit.object, p);
    // Shade the side the ray arrives on
    const Vec3 n = glm::dot(outward, q.ray.d) > 0.0 ? -outward : outward;
    const bool sphere = obj.shape == Shape::Sphere;
    // May a ray leaving p in direction d meet this object again? Into a sphere, yes; out
    // of a sphere or off a polygon, no (convexity); off a cone, it may (it is open)
    auto origin = [&](const Vec3& d) {
        return RayOrigin{hit.object, sphere ? glm::dot(d, outward) < 0.0 : obj.shape == Shape::Cone};
    };
    auto spawn = [&](RayKind kind, int light, const Ray& ray, double tmax, const Vec3& weight) {
        RayTask c;
        c.query = {ray, tmax, origin(ray.d), kind, light};
        c.pixel = task.pixel;
        c.node = paths.child(task.node, kind, light);
        c.depth = task.depth + 1;
        c.weight = weight;
        return c;
    };

    // [shade-local]
    image.add(task.pixel, task.weight * opt.ambient * m.kd * m.color);
    // Haines' SPD: n lights each of intensity 1/sqrt(n)
    const double lightScale = scene.lights.empty() ? 0.0 : 1.0 / std::sqrt(double(scene.lights.size()));
    for (int k = 0; k < int(scene.lights.size()); ++k) {
        const Light& light = scene.lights[k];
        const Vec3 toLight = light.position - p;
        const double dist = glm::length(toLight);
        if (!(dist > 0.0)) continue;
        const Vec3 l = toLight / dist;
        const double cosine = glm::dot(n, l);
        if (cosine <= 0.0) continue;  // the light is behind the surface
        const Vec3 r = glm::reflect(-l, n);
        const double spec = m.ks > 0.0 && m.shine > 0.0
                                ? m.ks * std::pow(std::max(0.0, glm::dot(r, -q.ray.d)), m.shine)
                                : 0.0;
        const Vec3 light_in = task.weight * light.color * lightScale * (m.kd * cosine * m.color + Vec3(spec));
        if (maxComponent(light_in) <= 0.0) continue;  // nothing to gain: no shadow ray
        // The shadow ray carries the light it would bring
        RayTask s = spawn(RayKind::Shadow, k, Ray{p, l}, dist, task.weight);
        s.unblocked = light_in;
        children.push_back(s);
    }
    // [shade-local]

    // [shade-spawn]
    if (task.depth >= opt.maxDepth) return;
    // Reflection, weighted by Ks
    const Vec3 wr = task.weight * m.ks;
    if (m.ks > 0.0 && maxComponent(wr) >= opt.cutoff && maxComponent(wr) > 0.0)
        children.push_back(spawn(RayKind::Reflection, -1, Ray{p, glm::normalize(glm::reflect(q.ray.d, n))}, kNoHit, wr));
    // Refraction, weighted by Kt; total internal reflection turns it back inside
    const Vec3 wt = task.weight * m.kt;
    if (m.kt > 0.0 && maxComponent(wt) >= opt.cutoff && maxComponent(wt) > 0.0) {
        Vec3 d = q.ray.d;  // a polygon or a cone is a thin sheet: straight through
        if (sphere) {
            const bool entering = glm::dot(q.ray.d, outward) < 0.0;
            const double eta = entering ? 1.0 / m.ior : m.ior;
            const Vec3 refracted = glm::refract(q.ray.d, n, eta);
            d = glm::dot(refracted, refracted) > 0.0 ? glm::normalize(refracted)
                                                     : glm::normalize(glm::reflect(q.ray.d, n));
        }
        children.push_back(spawn(RayKind::Refraction, -1, Ray{p, d}, kNoHit, wt));
    }
    // [shade-spawn]
}

}  // namespace rc
