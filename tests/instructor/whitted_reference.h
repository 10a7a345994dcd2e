#pragma once
// A second implementation of the classic image, for scenes of opaque spheres: Whitted's
// recursion (Whitted 1980) as a textbook writes it, every ray against every sphere, no
// ray tasks, no cache, no order. Only the intersection routine and the camera are the
// library's own; the shading is written out again from the model (SPD's 1/sqrt(n) lights,
// ambient 0.1, Phong highlights, mirror reflection weighted by Ks, depth 5 with the eye
// ray at depth 1). Each contribution is added into a fixed-point ImageAccumulator, as the
// renderer adds it, so the two images can be compared byte for byte.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geometry/intersection.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "trace/image_accumulator.h"

namespace rc::testing {

class WhittedReference {
public:
    explicit WhittedReference(const Scene& s) : s_(s) {
        for (const Object& o : s.objects)
            if (o.shape != Shape::Sphere || s.materials[o.material].kt > 0.0)
                throw std::invalid_argument("the reference traces opaque spheres only");
    }

    ImageAccumulator render(int width, int height) const {
        ImageAccumulator image(width, height);
        const RayGenerator camera(s_.camera, width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) trace(camera.primary(x, y), -1, 1, Vec3(1.0), y * width + x, image);
        return image;
    }

private:
    /// The nearest sphere along `ray` from a point on sphere `from` (-1: the eye), leaving it
    struct Hit {
        int object = -1;
        double t = kNoHit;
    };
    Hit nearest(const Ray& ray, int from, double tmax) const {
        Hit h;
        for (int i = 0; i < s_.size(); ++i) {
            const double t = intersectSphere(ray, s_.spheres[s_.objects[i].index], i == from ? Start::Leaving : Start::Elsewhere);
            if (t < h.t && t < tmax) h = {i, t};
        }
        return h;
    }

    void trace(const Ray& ray, int from, int depth, const Vec3& weight, int pixel, ImageAccumulator& image) const {
        const Hit h = nearest(ray, from, kNoHit);
        if (h.object < 0) {
            image.add(pixel, weight * s_.background);
            return;
        }
        const Material& m = s_.materials[s_.objects[h.object].material];
        const Vec3 p = ray.at(h.t);
        const Vec3 outward = s_.normal(h.object, p);
        const Vec3 n = glm::dot(outward, ray.d) > 0.0 ? -outward : outward;
        // Ambient, then each light that the surface faces and nothing blocks
        image.add(pixel, weight * 0.1 * m.kd * m.color);
        const double scale = s_.lights.empty() ? 0.0 : 1.0 / std::sqrt(double(s_.lights.size()));
        for (const Light& light : s_.lights) {
            const Vec3 toLight = light.position - p;
            const double dist = glm::length(toLight);
            const Vec3 l = toLight / dist;
            const double cosine = glm::dot(n, l);
            if (!(dist > 0.0) || cosine <= 0.0) continue;
            const Vec3 r = glm::reflect(-l, n);
            const double spec = m.ks > 0.0 && m.shine > 0.0 ? m.ks * std::pow(std::max(0.0, glm::dot(r, -ray.d)), m.shine) : 0.0;
            const Vec3 brought = weight * light.color * scale * (m.kd * cosine * m.color + Vec3(spec));
            if (std::max({brought.x, brought.y, brought.z}) <= 0.0) continue;
            if (nearest({p, l}, h.object, dist).object < 0) image.add(pixel, brought);
        }
        // The mirror ray, weighted by Ks
        if (depth >= 5 || !(m.ks > 0.0)) return;
        trace({p, glm::normalize(glm::reflect(ray.d, n))}, h.object, depth + 1, weight * m.ks, pixel, image);
    }

    const Scene& s_;
};

}  // namespace rc::testing
