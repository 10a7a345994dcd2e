#pragma once
/// \file
/// \brief The immutable scene: spheres, polygons, materials, lights, camera.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/sphere.h"
#include "geometry/truncated_cone.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/material.h"

namespace rc {

/// What kind of surface an object is.
enum class Shape : std::uint8_t { Sphere, Polygon, Cone };

/// One primitive of the scene. Polygons and cones take part in caching through `bound`,
/// their bounding sphere; for spheres `bound` is the sphere itself.
struct Object {
    Shape shape = Shape::Sphere;
    int index = 0;     ///< into Scene::spheres, Scene::polygons or Scene::cones
    int material = 0;  ///< into Scene::materials
    Sphere bound;
};

/// Where a ray starts: on no object (the eye), or on an object's surface, heading
/// out of it or into it.
struct RayOrigin {
    int object = -1;      ///< -1: a point that is on no surface (the eye)
    /// The ray may meet its own object again: it heads into a sphere's interior
    /// (refraction), or leaves a surface that is not convex (a cone). When false, the
    /// object is convex and the ray leaves it outward, so it cannot meet it again.
    bool inside = false;
    bool operator==(const RayOrigin&) const = default;
};

/// A scene, immutable once built. Object ids index `objects`.
struct Scene {
    std::string name;
    Camera camera;
    Vec3 background{0.0};
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    std::vector<Polygon> polygons;
    std::vector<TruncatedCone> cones;
    std::vector<Object> objects;
    Sphere bound;  ///< holds every object; set by finalize()
    /// What the reader skipped because no ray can hit it (a polygon of zero area), one
    /// `file:line:column: message` each, in file order; the first few only (the count is
    /// `skippedCount`), so that a file of nothing else stays small in memory.
    std::vector<std::string> skipped;
    long skippedCount = 0;

    /// Adds a material; returns its index.
    int addMaterial(const Material& m) {
        materials.push_back(m);
        return int(materials.size()) - 1;
    }
    /// Adds a sphere with a material index; returns its object id. Takes `s` by value: it
    /// may be an element of `spheres` itself, which the push may move.
    int addSphere(Sphere s, int material);
    /// Adds a polygon (made with makePolygon) with a material; returns its object id.
    int addPolygon(Polygon p, int material);
    /// Adds a cone (made with makeTruncatedCone) with a material; returns its object id.
    int addCone(const TruncatedCone& c, int material);
    /// Computes `bound`. Call once after the last add.
    void finalize();

    /// Hit distance of `ray` with object `id`, or kNoHit, for a ray starting at `origin`.
    double intersect(const Ray& ray, int id, const RayOrigin& origin) const;
    /// Outward unit normal of object `id` at surface point `p`.
    Vec3 normal(int id, const Vec3& p) const;
    const Material& material(int id) const { return materials[objects[id].material]; }
    int size() const { return int(objects.size()); }
    bool hasTransparency() const;
    /// Does the scene hold a shape of kind `s`?
    bool has(Shape s) const;
    /// The size of the scene's coordinates: how far from the origin its objects, eye and
    /// lights reach. Margins that absorb rounding are this times a few ulps.
    double extent() const;
};

/// The scene with every light a sphere of radius `radius` (distributed ray tracing's soft
/// shadows): `scene` itself when the radius is not positive or every light has it already,
/// else a copy.
std::shared_ptr<const Scene> withLightRadius(std::shared_ptr<const Scene> scene, double radius);

/// A scene that could not be read: `file:line:column: message`.
class SceneError : public std::runtime_error {
public:
    SceneError(std::string file, int line, int column, std::string message);
    std::string file;
    int line = 0;
    int column = 0;
    std::string message;
};

}  // namespace rc
