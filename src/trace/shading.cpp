#include "trace/shading.h"
#include "geometry/portable_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "trace/fresnel.h"

namespace rc {

namespace {
double maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
}  // namespace

void primaryTask(RayTask& t, const Ray& ray, int pixel, int sample, std::uint64_t key, double weight) {
    // What differs from a new task, one field at a time
    t.query.ray.o = ray.o;
    t.query.ray.d = ray.d;
    t.pixel = pixel;
    t.sample = sample;
    t.key = key;
    t.weight = Vec3(weight);
}

RayTask primaryTask(const Ray& ray, int pixel, int sample, std::uint64_t key, double weight) {
    RayTask t;
    primaryTask(t, ray, pixel, sample, key, weight);
    return t;
}

void shade(const Scene& scene, const RayTask& task, const Answer& hit, const ShadingOptions& opt,
           ImageAccumulator& image, std::vector<RayTask>& children) {
    const Query& q = task.query;
    // [shade-leaves]
    // A shadow ray that reaches its light brings the light it was carrying
    if (q.kind == RayKind::Shadow) {
        if (hit.object < 0) image.add(task.pixel, task.weight);
        return;
    }
    // A ray that hits nothing sees the background
    if (hit.object < 0) {
        image.add(task.pixel, task.weight * scene.background);
        return;
    }
    // [shade-leaves]
    // The surface hit: its material, the point, the normal on the ray's side
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
    // A child names its step; the render finds its path in the cache tree. It is built
    // where it is kept, field by field: a task built aside and copied in is read back in
    // wide loads from narrow stores still in flight, which stalls. So is a Ray built aside
    auto spawn = [&](RayKind kind, int light, int sample, const Vec3& d, double tmax,
                     const Vec3& weight) -> RayTask& {
        RayTask& c = children.emplace_back();
        c.query.ray.o = p;
        c.query.ray.d = d;
        c.query.tmax = tmax;
        c.query.origin = origin(d);
        c.query.kind = kind;
        c.query.light = light;
        c.pixel = task.pixel;
        c.node = -1;
        c.depth = task.depth + 1;
        c.sample = sample;
        c.key = childKey(task.key, kind, light, sample);
        c.weight = weight;
        return c;
    };
    const Sampling& sampling = opt.sampling;

    // [shade-local]
    image.add(task.pixel, task.weight * opt.ambient * m.kd * m.color);
    // Haines' SPD: n lights each of intensity 1/sqrt(n)
    const double lightScale = scene.lights.empty() ? 0.0 : 1.0 / std::sqrt(double(scene.lights.size()));
    for (int k = 0; k < int(scene.lights.size()); ++k) {
        const Light& light = scene.lights[k];
        // A point light gets one shadow ray; a spherical one K, to points of its sphere,
        // each bringing 1/K of what it would bring alone
        const int samples = light.radius > 0.0 ? sampling.shadowSamples : 1;
        for (int j = 0; j < samples; ++j) {
            const Vec3 target = light.radius > 0.0
                                    ? lightSample(light, p, childKey(task.key, RayKind::Shadow, k, j))
                                    : light.position;
            const Vec3 toLight = target - p;
            const double dist = glm::length(toLight);
            if (!(dist > 0.0)) continue;
            const Vec3 l = toLight / dist;
            const double cosine = glm::dot(n, l);
            if (cosine <= 0.0) continue;  // the light is behind the surface
            const Vec3 r = glm::reflect(-l, n);
            const double spec = m.ks > 0.0 && m.shine > 0.0
                                    ? m.ks * pm::pow(std::max(0.0, glm::dot(r, -q.ray.d)), m.shine)
                                    : 0.0;
            Vec3 light_in = task.weight * light.color * lightScale * (m.kd * cosine * m.color + Vec3(spec));
            if (samples > 1) light_in /= double(samples);
            if (maxComponent(light_in) <= 0.0) continue;  // nothing to gain: no shadow ray
            // The shadow ray carries the light it would bring
            spawn(RayKind::Shadow, k, j, l, dist, light_in);
        }
    }
    // [shade-local]

    // [shade-spawn]
    if (task.depth >= opt.maxDepth) return;
    // A transmitter is a dielectric: its boundary reflects what Fresnel's equations give
    // and lets the rest of Kt through, nothing beyond the critical angle
    const bool entering = glm::dot(q.ray.d, outward) < 0.0;
    const double fresnel = m.kt > 0.0 ? fresnelDielectric(-glm::dot(q.ray.d, n), entering ? 1.0 : m.ior,
                                                          entering ? m.ior : 1.0)
                                      : 0.0;
    // Reflection, weighted by Ks, or by Fresnel where that is larger: every transmitter
    // also reflects (SPD's rules 8 and 9)
    const double kr = std::max(m.ks, fresnel);
    const Vec3 wr = task.weight * kr;
    if (kr > 0.0 && maxComponent(wr) >= opt.cutoff && maxComponent(wr) > 0.0) {
        const Vec3 mirror = glm::normalize(glm::reflect(q.ray.d, n));
        if (!(sampling.glossDegrees > 0.0)) {
            spawn(RayKind::Reflection, -1, 0, mirror, kNoHit, wr);
        } else {
            // Glossy: K directions in the cone around the mirror direction, each 1/K of
            // the weight; one that dips under the surface is mirrored back above it
            const double halfAngle = sampling.glossDegrees * std::numbers::pi / 180.0;
            const int samples = sampling.glossSamples;
            for (int j = 0; j < samples; ++j) {
                Vec3 d = coneSample(mirror, halfAngle, childKey(task.key, RayKind::Reflection, -1, j));
                const double below = glm::dot(d, n);
                if (below <= 0.0) d = glm::normalize(d - 2.0 * below * n);
                spawn(RayKind::Reflection, -1, j, d, kNoHit, wr / double(samples));
            }
        }
    }
    // Refraction, weighted by the part of Kt that the boundary lets through (Snell's law
    // bends it into a sphere; a polygon or a cone is a thin sheet: straight through)
    const Vec3 wt = task.weight * (m.kt * (1.0 - fresnel));
    if (m.kt > 0.0 && fresnel < 1.0 && maxComponent(wt) >= opt.cutoff && maxComponent(wt) > 0.0) {
        Vec3 d = q.ray.d;
        if (sphere) {
            const Vec3 refracted = glm::refract(q.ray.d, n, entering ? 1.0 / m.ior : m.ior);
            if (!(glm::dot(refracted, refracted) > 0.0)) return;  // grazing the critical angle
            d = glm::normalize(refracted);
        }
        spawn(RayKind::Refraction, -1, 0, d, kNoHit, wt);
    }
    // [shade-spawn]
}

}  // namespace rc
