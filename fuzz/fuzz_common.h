// Shared by the fuzz targets: checks that survive NDEBUG and stop the fuzzer with a
// message (libFuzzer then saves the input as a crash), and the invariants every scene
// the reader returns, and every error it throws, must satisfy.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/nff_reader.h"

#define FUZZ_CHECK(cond)                                                                       \
    do {                                                                                       \
        if (!(cond)) {                                                                         \
            std::fprintf(stderr, "%s:%d: FUZZ_CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                      \
        }                                                                                      \
    } while (0)

namespace rc::fuzz {

inline bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// What parseNff promises about a scene it returns.
inline void checkScene(const Scene& s) {
    FUZZ_CHECK(s.objects.size() == s.spheres.size() + s.polygons.size() + s.cones.size());
    FUZZ_CHECK(s.camera.width >= 1 && s.camera.width <= NffLimits::maxResolution);
    FUZZ_CHECK(s.camera.height >= 1 && s.camera.height <= NffLimits::maxResolution);
    FUZZ_CHECK(s.camera.angle > 0.0 && s.camera.angle < 180.0);
    FUZZ_CHECK(finite(s.camera.from) && finite(s.camera.at) && finite(s.camera.up));
    FUZZ_CHECK(std::isfinite(s.bound.r) && s.bound.r >= 0.0 && finite(s.bound.c));
    for (const Object& o : s.objects) {
        FUZZ_CHECK(o.material >= 0 && o.material < int(s.materials.size()));
        if (o.shape == Shape::Sphere) FUZZ_CHECK(o.index >= 0 && o.index < int(s.spheres.size()));
        else if (o.shape == Shape::Cone) FUZZ_CHECK(o.index >= 0 && o.index < int(s.cones.size()));
        else FUZZ_CHECK(o.index >= 0 && o.index < int(s.polygons.size()));
        FUZZ_CHECK(std::isfinite(o.bound.r) && finite(o.bound.c));
    }
    for (const Sphere& sp : s.spheres) FUZZ_CHECK(sp.r > 0.0 && std::isfinite(sp.r) && finite(sp.c));
    for (const TruncatedCone& c : s.cones)
        FUZZ_CHECK(c.height > 0.0 && std::isfinite(c.height) && c.baseRadius >= 0.0 && c.apexRadius >= 0.0 &&
                   (c.baseRadius > 0.0 || c.apexRadius > 0.0) && finite(c.base) && finite(c.axis));
    for (const Polygon& p : s.polygons) {
        FUZZ_CHECK(p.vertices.size() >= 3);
        FUZZ_CHECK(p.vertices.size() <= std::size_t(NffLimits::maxPolygonVertices));
        FUZZ_CHECK(finite(p.normal));
        FUZZ_CHECK(p.vertexNormals.empty() || p.vertexNormals.size() == p.vertices.size());
    }
    for (const Material& m : s.materials) FUZZ_CHECK(finite(m.color) && m.ior > 0.0);
    for (const Light& l : s.lights) FUZZ_CHECK(finite(l.position) && finite(l.color));
}

/// What every SceneError from an in-memory parse looks like: `file:line:column: message`.
inline void checkError(const SceneError& e, const std::string& file) {
    FUZZ_CHECK(e.file == file);
    FUZZ_CHECK(e.line >= 1 && e.column >= 1);
    FUZZ_CHECK(!e.message.empty());
    const std::string prefix = file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ";
    FUZZ_CHECK(std::string(e.what()).rfind(prefix, 0) == 0);
}

}  // namespace rc::fuzz
