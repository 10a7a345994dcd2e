#pragma once
// Random scenes that stress the caches: overlapping, tangent, nested and transparent
// spheres, and polygons.
#include <string>

#include <glm/geometric.hpp>

#include "scene/scene.h"
#include "uniform.h"

namespace rc::testing {

enum class Layout { Overlapping, Tangent, Nested, Transparent, Polygons };

inline const char* name(Layout l) {
    switch (l) {
        case Layout::Overlapping: return "overlapping";
        case Layout::Tangent: return "tangent";
        case Layout::Nested: return "nested";
        case Layout::Transparent: return "transparent";
        case Layout::Polygons: return "polygons";
    }
    return "?";
}

inline Scene randomScene(Layout layout, std::uint64_t seed, int count = 24) {
    Random rng(seed);
    const Uniform u{-1.0, 1.0};
    Scene s;
    s.name = std::string(name(layout)) + "-" + std::to_string(seed);
    s.background = Vec3(0.2, 0.3, 0.5);
    s.materials.push_back({Vec3(0.9, 0.4, 0.3), 0.7, 0.3, 20.0, 0.0, 1.0});
    s.materials.push_back({Vec3(0.3, 0.8, 0.4), 0.6, 0.5, 40.0, 0.0, 1.0});
    s.materials.push_back({Vec3(1.0), 0.1, 0.2, 60.0, 0.8, 1.5});  // glass
    s.lights.push_back({Vec3(5, 6, 8), Vec3(1.0)});
    s.lights.push_back({Vec3(-6, 4, 3), Vec3(0.8, 0.8, 1.0)});
    auto mat = [&](int i) {
        if (layout == Layout::Transparent) return i % 3 == 0 ? 2 : i % 2;
        return i % 2;
    };
    for (int i = 0; i < count; ++i) {
        const Vec3 c(2.5 * u(rng), 2.5 * u(rng), 2.5 * u(rng));
        double r = 0.2 + 0.5 * std::abs(u(rng));
        if (layout == Layout::Nested && i % 2 == 1) {
            // inside the previous sphere
            const Sphere& outer = s.spheres.back();
            r = outer.r * 0.4;
            s.addSphere({outer.c + Vec3(u(rng), u(rng), u(rng)) * (outer.r * 0.3), r}, 2);
            continue;
        }
        if (layout == Layout::Tangent && i > 0) {
            // touching the previous sphere
            const Sphere& prev = s.spheres.back();
            const Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            s.addSphere({prev.c + dir * (prev.r + r), r}, mat(i));
            continue;
        }
        s.addSphere({c, r}, mat(i));
    }
    if (layout == Layout::Polygons || layout == Layout::Transparent) {
        Polygon ground;
        makePolygon({{-6, -3, -6}, {6, -3, -6}, {6, -3, 6}, {-6, -3, 6}}, {}, ground);
        s.addPolygon(ground, 0);
        for (int i = 0; i < 4; ++i) {
            Polygon tri;
            const Vec3 c(2.5 * u(rng), 2.5 * u(rng), 2.5 * u(rng));
            if (!makePolygon({c, c + Vec3(1.0, 0.2 * u(rng), 0.0), c + Vec3(0.3, 1.0, 0.4 * u(rng))}, {}, tri))
                s.addPolygon(tri, i % 2 ? 1 : 2);
        }
    }
    s.camera.from = Vec3(0.5, 1.0, 9.0);
    s.camera.at = Vec3(0.0);
    s.camera.up = Vec3(0, 1, 0);
    s.camera.angle = 45.0;
    s.camera.width = s.camera.height = 40;
    s.finalize();
    return s;
}

}  // namespace rc::testing
