#include "search/sphere_batch.h"

#include <experimental/simd>

namespace stdx = std::experimental;

namespace rc {

void SphereBatch::add(const Scene& scene, int id) {
    const Object& o = scene.objects[id];
    const bool sphere = o.shape == Shape::Sphere;
    // The very sphere Scene::intersect() tests, so both compute the same discriminant
    const Sphere s = sphere ? scene.spheres[o.index] : o.bound;
    ids_.push_back(id);
    idValues_.push_back(double(id));
    x_.push_back(s.c.x);
    y_.push_back(s.c.y);
    z_.push_back(s.c.z);
    radius2_.push_back(sphere ? s.r * s.r : -1.0);
    bound_.push_back(o.bound.r);
}

void SphereBatch::clearance(const Vec3& a, const Vec3& ab, double invLen2, int skip, int skipToo,
                            std::size_t begin, std::size_t end, double& clearance) const {
    // [segment-clearance]
    // Every sphere's distance from the segment, the least kept: a few spheres at once (as
    // many as a vector register holds), with no branch and no dependence between them
    using Lanes = stdx::native_simd<double>;
    constexpr std::size_t kLanes = Lanes::size();
    auto distance = [&](const auto& x, const auto& y, const auto& z, const auto& bound) {
        const auto px = x - a.x, py = y - a.y, pz = z - a.z;
        const auto t = stdx::clamp((px * ab.x + py * ab.y + pz * ab.z) * invLen2, decltype(px)(0.0), decltype(px)(1.0));
        const auto qx = px - t * ab.x, qy = py - t * ab.y, qz = pz - t * ab.z;
        return stdx::sqrt(qx * qx + qy * qy + qz * qz) - bound;
    };
    Lanes least = clearance;
    std::size_t i = begin;
    for (; i + kLanes <= end; i += kLanes) {
        auto load = [&](const std::vector<double>& v) { return Lanes(&v[i], stdx::element_aligned); };
        Lanes d = distance(load(x_), load(y_), load(z_), load(bound_));
        // The segment's own ends (the object it leaves, the one it reaches) are left out
        const Lanes id = load(idValues_);
        stdx::where(id == double(skip) || id == double(skipToo), d) = least;
        stdx::where(d < least, least) = d;
    }
    double result = stdx::hmin(least);
    // The few left over, one at a time
    using One = stdx::fixed_size_simd<double, 1>;
    for (; i < end; ++i) {
        if (ids_[i] == skip || ids_[i] == skipToo) continue;
        result = std::min(result, double(distance(One(x_[i]), One(y_[i]), One(z_[i]), One(bound_[i]))[0]));
    }
    clearance = result;
    // [segment-clearance]
}

}  // namespace rc
