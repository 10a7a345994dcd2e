#include "study/stiff_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"
#include "scene/random.h"

namespace rc {

namespace {


int material(Scene& s, Vec3 color, double kd, double ks, double shine, double kt = 0.0, double ior = 1.0) {
    return s.addMaterial({color, kd, ks, shine, kt, ior});
}

void view(Scene& s, Vec3 from, Vec3 at, double angle, int size = 64) {
    s.camera.from = from;
    s.camera.at = at;
    s.camera.up = Vec3(0, 1, 0);
    s.camera.angle = angle;
    s.camera.hither = 1e-3;
    s.camera.width = s.camera.height = size;
}

// Spheres whose silhouettes the eye rays of chosen pixels touch exactly (as exactly as
// the radius, computed from the double ray, can say)
Scene grazing() {
    Scene s;
    s.name = "gen:grazing";
    s.background = Vec3(0.2, 0.3, 0.5);
    const int red = material(s, Vec3(0.9, 0.3, 0.25), 0.6, 0.4, 30.0);
    const int glass = material(s, Vec3(1.0), 0.05, 0.15, 100.0, 0.85, 1.5);
    const int floor = material(s, Vec3(0.7), 0.9, 0.1, 10.0);
    view(s, Vec3(0, 0.5, 10), Vec3(0, 0, 0), 40.0);
    RayGenerator cam(s.camera, 64, 64);
    const int pixels[][2] = {{16, 16}, {40, 20}, {20, 45}, {48, 48}, {31, 31}, {8, 40}};
    const Vec3 sideways[] = {Vec3(1, 0.3, 0), Vec3(-0.2, 1, 0.1), Vec3(0.5, -1, 0.2),
                             Vec3(-1, -0.4, 0.3), Vec3(0.7, 0.7, 0), Vec3(0, 1, -0.5)};
    for (int i = 0; i < 6; ++i) {
        const Ray ray = cam.primary(pixels[i][0], pixels[i][1]);
        // A centre beside the ray; the radius is its distance from the ray
        const Vec3 side = glm::normalize(sideways[i] - glm::dot(sideways[i], ray.d) * ray.d);
        const double along = 8.0 + 0.5 * i;
        const Vec3 c = ray.at(along) + (0.4 + 0.1 * i) * side;
        const Vec3 f = ray.o - c;
        const Vec3 l = f - glm::dot(f, ray.d) * ray.d;
        s.addSphere({c, glm::length(l)}, i == 4 ? glass : red);
    }
    Polygon p;
    makePolygon({Vec3(-6, -2, -6), Vec3(6, -2, -6), Vec3(6, -2, 6), Vec3(-6, -2, 6)}, {}, p);
    s.addPolygon(std::move(p), floor);
    // A light whose rays to the floor graze the first sphere
    s.lights.push_back({Vec3(3, 6, 4), Vec3(1.0)});
    s.lights.push_back({Vec3(-5, 2, 6), Vec3(0.7)});
    s.finalize();
    return s;
}

// Mirror pairs whose hull is nearly a cylinder, with small spheres 1e-12 outside and
// inside the hull's surface
Scene nearCylinder() {
    Scene s;
    s.name = "gen:near_cylinder";
    s.background = Vec3(0.2, 0.3, 0.5);
    const int mirror = material(s, Vec3(0.9, 0.9, 1.0), 0.3, 0.7, 60.0);
    const int red = material(s, Vec3(0.9, 0.3, 0.25), 0.6, 0.4, 30.0);
    const int green = material(s, Vec3(0.3, 0.8, 0.35), 0.6, 0.4, 30.0);
    view(s, Vec3(0.5, 4, 7), Vec3(0, 0, 0), 50.0);
    s.addSphere({Vec3(-3, 0, 0), 1.0}, mirror);
    s.addSphere({Vec3(3, 0, 0), 1.0 + 1e-13}, mirror);
    s.addSphere({Vec3(-3, 0, 3), 0.7}, mirror);
    s.addSphere({Vec3(3, 0, 3), 0.7}, mirror);  // exactly a cylinder
    for (int i = 0; i < 4; ++i) {
        const double x = -1.5 + i;
        const double gap = (i % 2 ? 1e-12 : -1e-12);
        s.addSphere({Vec3(x, 1.0 + 0.1 + gap, 0.0), 0.1}, i % 2 ? red : green);
        s.addSphere({Vec3(x, 0.0, -(1.0 + 0.15 - gap)), 0.15}, i % 2 ? green : red);
        s.addSphere({Vec3(x + 0.5, 0.0, 3.0 + 0.7 + 0.2 + gap), 0.2}, red);
    }
    s.lights.push_back({Vec3(0, 6, 5), Vec3(1.0)});
    s.lights.push_back({Vec3(-4, 3, 8), Vec3(0.6)});
    s.finalize();
    return s;
}

// Pairs whose hull is nearly degenerate: a smaller sphere that sticks out of a bigger
// one by 1e-4, 1e-9 and 1e-13 of its radius (the tangent cone's half-angle is nearly 90
// degrees), mirrors all, with small spheres near the protrusions
Scene degenerateCone() {
    Scene s;
    s.name = "gen:degenerate_cone";
    s.background = Vec3(0.2, 0.3, 0.5);
    const int mirror = material(s, Vec3(0.9, 0.9, 1.0), 0.3, 0.7, 60.0);
    const int red = material(s, Vec3(0.9, 0.3, 0.25), 0.6, 0.4, 30.0);
    const int glass = material(s, Vec3(1.0), 0.05, 0.15, 100.0, 0.85, 1.5);
    view(s, Vec3(0, 3, 9), Vec3(0, 0, 0), 50.0);
    const double sticks[] = {1e-4, 1e-9, 1e-13};
    const Vec3 dirs[] = {glm::normalize(Vec3(1, 1, 1)), glm::normalize(Vec3(-1, 1, 2)),
                         glm::normalize(Vec3(0.3, 1, 0.8))};
    for (int i = 0; i < 3; ++i) {
        const Vec3 c((i - 1) * 3.0, 0.0, 0.0);
        const double R = 1.2, r = 0.5;
        s.addSphere({c, R}, mirror);
        // D = R - r + stick: the small sphere pokes out of the big one by `stick`
        const double D = R - r + sticks[i];
        s.addSphere({c + D * dirs[i], r}, i == 1 ? glass : mirror);
        // A sphere just touching the protrusion, and one near the big sphere
        const Vec3 tip = c + (D + r) * dirs[i];
        s.addSphere({tip + 0.1 * dirs[i] + Vec3(1e-12, 0, 0), 0.1}, red);
        s.addSphere({c + (R + 0.3) * glm::normalize(dirs[i] + Vec3(0.4, 0, 0)), 0.25}, red);
    }
    Polygon p;
    makePolygon({Vec3(-8, -1.3, -8), Vec3(8, -1.3, -8), Vec3(8, -1.3, 8), Vec3(-8, -1.3, 8)}, {}, p);
    s.addPolygon(std::move(p), mirror);
    s.lights.push_back({Vec3(2, 8, 6), Vec3(1.0)});
    s.lights.push_back({Vec3(-6, 4, 4), Vec3(0.6)});
    s.finalize();
    return s;
}

// The paper's cube of spheres with every coordinate offset by 1e7
Scene offsetCube() {
    Scene base = makeBuiltin("cube:3");
    Scene s;
    s.name = "gen:offset_cube";
    s.background = base.background;
    s.materials = base.materials;
    const Vec3 shift(1e7, -1e7, 1e7);
    for (const Object& o : base.objects) {
        Sphere sp = base.spheres[o.index];
        sp.c += shift;
        s.addSphere(sp, o.material);
    }
    for (Light l : base.lights) {
        l.position += shift;
        s.lights.push_back(l);
    }
    s.camera = base.camera;
    s.camera.from += shift;
    s.camera.at += shift;
    s.camera.width = s.camera.height = 48;
    s.finalize();
    return s;
}

// Radii spanning four decades, overlapping at random, mirrors and glass among them
Scene radiusSpan() {
    Scene s;
    s.name = "gen:radius_span";
    s.background = Vec3(0.2, 0.3, 0.5);
    const int mats[] = {material(s, Vec3(0.9, 0.3, 0.25), 0.6, 0.4, 30.0),
                        material(s, Vec3(0.3, 0.8, 0.35), 0.7, 0.0, 0.0),
                        material(s, Vec3(0.9, 0.9, 1.0), 0.2, 0.8, 80.0),
                        material(s, Vec3(1.0), 0.05, 0.15, 100.0, 0.85, 1.5)};
    view(s, Vec3(0.3, 0.8, 6), Vec3(0, 0, 0), 45.0);
    Random u(1986);
    for (int i = 0; i < 48; ++i) {
        const Vec3 c(4 * u() - 2, 4 * u() - 2, 4 * u() - 2);
        const double r = std::pow(10.0, -4.0 + 4.0 * u()) * 0.8;
        s.addSphere({c, r}, mats[i % 4]);
    }
    s.lights.push_back({Vec3(4, 6, 6), Vec3(1.0)});
    s.lights.push_back({Vec3(-5, 3, 5), Vec3(0.7)});
    s.finalize();
    return s;
}

std::string firstComment(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        const auto p = line.find_first_not_of(" \t");
        if (p == std::string::npos) continue;
        if (line[p] != '#') return "";
        std::string text = line.substr(p + 1);
        text.erase(0, text.find_first_not_of(" \t"));
        while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
        return text;
    }
    return "";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> stiffGenerators() {
    return {{"gen:grazing", "eye rays of chosen pixels touch sphere silhouettes exactly"},
            {"gen:near_cylinder", "blocker hulls nearly a cylinder (radii 1 and 1 + 1e-13), blockers 1e-12 off the hull"},
            {"gen:degenerate_cone", "hulls nearly degenerate: spheres sticking out of bigger ones by 1e-4, 1e-9, 1e-13"},
            {"gen:offset_cube", "cube:3 with every coordinate offset by 1e7"},
            {"gen:radius_span", "48 overlapping spheres, radii from 8e-5 to 0.8, mirrors and glass"}};
}

Scene makeStiffScene(const std::string& name) {
    if (name == "gen:grazing") return grazing();
    if (name == "gen:near_cylinder") return nearCylinder();
    if (name == "gen:degenerate_cone") return degenerateCone();
    if (name == "gen:offset_cube") return offsetCube();
    if (name == "gen:radius_span") return radiusSpan();
    throw SceneError(name, 0, 0, "unknown stiff scene generator");
}

std::vector<StiffScene> loadStiffSuite(const std::string& dir) {
    std::vector<StiffScene> suite;
    for (const auto& [name, description] : stiffGenerators())
        suite.push_back({name, description, std::make_shared<const Scene>(makeStiffScene(name))});
    if (dir.empty()) return suite;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().extension() == ".nff") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files)
        suite.push_back({f.stem().string(), firstComment(f),
                         std::make_shared<const Scene>(readNffFile(f.string()))});
    return suite;
}

std::string defaultStiffSuiteDir() {
    // The environment's RAYCACHE_STIFF_DIR, else the folder CMake was configured with
    const char* env = std::getenv("RAYCACHE_STIFF_DIR");
#ifdef RAYCACHE_STIFF_DIR
    const std::filesystem::path dir = env && *env ? env : RAYCACHE_STIFF_DIR;
#else
    if (!env || !*env) return "";
    const std::filesystem::path dir = env;
#endif
    std::error_code ec;
    return std::filesystem::is_directory(dir, ec) ? dir.string() : "";
}

}  // namespace rc
