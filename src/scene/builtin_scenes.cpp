#include "scene/builtin_scenes.h"
#include "geometry/portable_math.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <filesystem>
#include <system_error>

#include <glm/geometric.hpp>

#include "scene/nff_reader.h"
#include "scene/random.h"
#include "scene/sphereflake.h"

namespace rc {

namespace {

constexpr int kMaxCube = 64;


const std::array<Vec3, 5> kPalette = {Vec3(0.90, 0.30, 0.25), Vec3(0.30, 0.80, 0.35),
                                      Vec3(0.30, 0.45, 0.90), Vec3(0.95, 0.80, 0.30),
                                      Vec3(0.85, 0.85, 0.85)};

// [cube-scene]
/// After the paper's Table 1 scene: an N x N x N lattice of jittered spheres (the details
/// are RayCache's, see docs/pages/table1.md).
Scene makeCube(int n, std::uint64_t seed) {
    Scene s;
    s.name = "cube:" + std::to_string(n);
    s.background = Vec3(0.15, 0.18, 0.24);
    int materials[kPalette.size()];
    for (std::size_t i = 0; i < kPalette.size(); ++i)
        materials[i] = s.addMaterial({kPalette[i], 0.6, 0.4, 30.0});
    Random rnd(seed);
    const double half = 0.5 * (n - 1);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                // Unit lattice, each centre jittered by up to +-0.15, radius in [0.25, 0.45]
                Sphere sp;
                sp.c.x = i - half + rnd.uniform(-0.15, 0.15);
                sp.c.y = j - half + rnd.uniform(-0.15, 0.15);
                sp.c.z = k - half + rnd.uniform(-0.15, 0.15);
                sp.r = rnd.uniform(0.25, 0.45);
                s.addSphere(sp, materials[rnd.index(int(kPalette.size()))]);
            }
    s.finalize();

    // Seen from a corner, far enough that the bounding sphere just fits the view cone
    Camera& cam = s.camera;
    cam.angle = 40.0;
    cam.hither = 1e-3;
    cam.width = cam.height = 512;
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.at = s.bound.c;
    const double dist = s.bound.r / pm::sin(0.5 * cam.angle * std::numbers::pi / 180.0);
    cam.from = cam.at + dist * glm::normalize(Vec3(1.0, 0.8, 1.3));

    // Two lights above the camera, one to each side, so that spheres cast shadows
    const Vec3 forward = glm::normalize(cam.at - cam.from);
    const Vec3 right = glm::normalize(glm::cross(forward, cam.up));
    const Vec3 up = glm::cross(right, forward);
    s.lights.push_back({cam.from + dist * (0.6 * up + 0.5 * right), Vec3(0.7)});
    s.lights.push_back({cam.from + dist * (0.9 * up - 0.7 * right), Vec3(0.5)});
    return s;
}
// [cube-scene]

/// Glass spheres in front of and among opaque ones, on a ground square.
Scene makeGlass(std::uint64_t seed) {
    Scene s;
    s.name = "glass";
    s.background = Vec3(0.20, 0.25, 0.35);
    const int ground = s.addMaterial({Vec3(0.75, 0.75, 0.70), 0.9, 0.0, 0.0});
    const int glass = s.addMaterial({Vec3(1.0), 0.05, 0.15, 100.0, 0.85, 1.5});
    const int red = s.addMaterial({kPalette[0], 0.7, 0.3, 40.0});
    const int green = s.addMaterial({kPalette[1], 0.7, 0.3, 40.0});
    const int blue = s.addMaterial({kPalette[2], 0.7, 0.3, 40.0});
    const int gold = s.addMaterial({kPalette[3], 0.7, 0.3, 40.0});

    // Ground: a 16 x 16 square at y = 0, normal up
    Polygon floor;
    if (auto err = makePolygon({Vec3(-8, 0, 8), Vec3(8, 0, 8), Vec3(8, 0, -8), Vec3(-8, 0, -8)}, {}, floor))
        throw SceneError("glass", 0, 0, *err);
    s.addPolygon(std::move(floor), ground);

    // Spheres stand on the ground: centre height = radius
    const auto stand = [](double x, double z, double r) { return Sphere{Vec3(x, r, z), r}; };
    s.addSphere(stand(-1.8, -1.5, 1.0), red);
    s.addSphere(stand(1.6, -2.0, 0.8), blue);
    s.addSphere(stand(0.2, -3.5, 0.6), green);
    s.addSphere(stand(-0.6, 1.2, 0.9), glass);  // in front
    s.addSphere(stand(1.4, 0.6, 0.6), glass);   // in front
    s.addSphere(stand(0.1, -1.0, 0.7), glass);  // among the opaque ones

    // A few marbles scattered by the seed, never overlapping anything
    Random rnd(seed);
    const int colours[] = {red, green, blue, gold, glass};
    int placed = 0;
    for (int attempt = 0; attempt < 400 && placed < 10; ++attempt) {
        const double r = rnd.uniform(0.15, 0.3);
        // One draw a statement: the order of a call's arguments is the compiler's (GCC's
        // right to left, clang's left to right)
        const double z = rnd.uniform(-5.0, 3.0);
        const double x = rnd.uniform(-4.0, 4.0);
        const Sphere m = stand(x, z, r);
        const int colour = colours[rnd.index(5)];
        bool free = true;
        for (const Sphere& o : s.spheres) free = free && glm::length(o.c - m.c) > o.r + m.r + 0.02;
        if (!free) continue;
        s.addSphere(m, colour);
        ++placed;
    }

    Camera& cam = s.camera;
    cam.from = Vec3(0.0, 2.2, 8.0);
    cam.at = Vec3(0.0, 0.8, 0.0);
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.angle = 45.0;
    cam.hither = 1e-3;
    cam.width = cam.height = 512;
    s.lights.push_back({Vec3(-4.0, 6.0, 5.0), Vec3(0.6)});
    s.lights.push_back({Vec3(5.0, 8.0, 2.0), Vec3(0.6)});
    s.finalize();
    return s;
}

/// One diffuse sphere that fills the view; the light sits beside the eye.
Scene makeFill() {
    Scene s;
    s.name = "fill";
    s.background = Vec3(0.0);
    s.addSphere(Sphere{Vec3(0.0), 1.0}, s.addMaterial({Vec3(0.8, 0.6, 0.4), 0.9, 0.0, 0.0}));
    // From 1.6 radii the sphere subtends asin(1/1.6) = 38.7 degrees; the corner rays of
    // a 40 degree view are atan(sqrt(2) tan 20) = 27.2 degrees off axis
    Camera& cam = s.camera;
    cam.from = Vec3(0.0, 0.0, 1.6);
    cam.at = Vec3(0.0);
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.angle = 40.0;
    cam.hither = 1e-3;
    cam.width = cam.height = 64;
    s.lights.push_back({Vec3(0.15, 0.2, 1.75), Vec3(1.0)});
    s.finalize();
    return s;
}

/// The paper's Figure 2: a reflected ray from the big sphere hits the small one.
Scene makePair() {
    Scene s;
    s.name = "pair";
    s.background = Vec3(0.10, 0.10, 0.15);
    s.addSphere(Sphere{Vec3(0.0), 1.0}, s.addMaterial({Vec3(0.85, 0.85, 0.9), 0.15, 0.85, 100.0}));
    s.addSphere(Sphere{Vec3(1.1, 0.7, 1.4), 0.35}, s.addMaterial({kPalette[0], 0.8, 0.2, 20.0}));
    Camera& cam = s.camera;
    cam.from = Vec3(0.0, 0.3, 5.0);
    cam.at = Vec3(0.0);
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.angle = 40.0;
    cam.hither = 1e-3;
    cam.width = cam.height = 256;
    s.lights.push_back({Vec3(-3.0, 4.0, 5.0), Vec3(1.0)});
    s.finalize();
    return s;
}

// [trio-scene]
/// The paper's Figure 2 with its blocker: a ray reflects off the big mirror sphere and
/// hits the small one, and a third sphere lies in the hull between the two, off the
/// reflected rays' way: the one potential blocker on their list.
Scene makeTrio() {
    Scene s;
    s.name = "trio";
    s.background = Vec3(0.10, 0.10, 0.15);
    s.addSphere(Sphere{Vec3(0.0), 1.0}, s.addMaterial({Vec3(0.85, 0.85, 0.9), 0.15, 0.85, 100.0}));
    s.addSphere(Sphere{Vec3(2.4, 0.5, 1.0), 0.45}, s.addMaterial({kPalette[0], 0.8, 0.2, 20.0}));
    // Half way along the axis from the big sphere to the small one, 0.36 off it: inside
    // their hull, whose radius there is about 0.72
    s.addSphere(Sphere{Vec3(1.15, 0.6, 0.45), 0.15}, s.addMaterial({kPalette[2], 0.8, 0.2, 20.0}));
    Camera& cam = s.camera;
    cam.from = Vec3(0.6, 0.6, 6.5);
    cam.at = Vec3(0.9, 0.3, 0.4);
    cam.up = Vec3(0.0, 1.0, 0.0);
    cam.angle = 45.0;
    cam.hither = 1e-3;
    cam.width = cam.height = 256;
    s.lights.push_back({Vec3(-3.0, 4.0, 5.0), Vec3(1.0)});
    s.finalize();
    return s;
}
// [trio-scene]

/// The N of `prefix:N` (a whole number from 1 to `max`, nothing around it).
/// \throws SceneError naming `what` and giving `usage`
int sizeOf(const std::string& spec, const std::string& prefix, int max, const char* what,
           const std::string& usage) {
    const std::string digits = spec.substr(prefix.size());
    int n = 0;
    const char* first = digits.data();
    const char* last = first + digits.size();
    const auto [ptr, ec] = std::from_chars(first, last, n);
    if (digits.empty() || digits[0] < '0' || digits[0] > '9' || ec != std::errc() || ptr != last || n < 1 ||
        n > max)
        throw SceneError(spec, 0, 0, std::string("bad ") + what + " size '" + digits + "': " + usage);
    return n;
}

bool endsWithNff(const std::string& s) {
    if (s.size() < 4) return false;
    const std::string tail = s.substr(s.size() - 4);
    return tail == ".nff" || tail == ".NFF" || tail == ".Nff";
}

}  // namespace

// [scene-registry]
const Registry<BuiltinInfo>& builtinScenes() {
    static const Registry<BuiltinInfo> r = [] {
        Registry<BuiltinInfo> b;
        b.add({"cube:N",
               "N^3 jittered reflective spheres on a lattice (1 <= N <= " + std::to_string(kMaxCube) +
                   "), after the paper's Table 1 scene",
               {2, 3, 4, 5, 6, 8}, kMaxCube, "", [](int n, std::uint64_t seed) { return makeCube(n, seed); }});
        b.add({"balls:N",
               "SPD's sphereflake of size N (1 <= N <= " + std::to_string(kMaxSphereflake) +
                   "): 1 + 9 + ... + 9^N mirrored spheres on a ground square; SPD's default is balls:4",
               {1, 2, 3, 4, 5}, kMaxSphereflake,
               "balls:" + std::to_string(kMaxSphereflake) + " has " +
                   std::to_string(sphereflakeSpheres(kMaxSphereflake)) + " spheres",
               [](int n, std::uint64_t) { return makeSphereflake(n); }});
        b.add({"glass", "refracting glass spheres in front of and among opaque ones, on a ground square", {}, 0, "",
               [](int, std::uint64_t seed) { return makeGlass(seed); }});
        b.add({"fill", "one diffuse sphere filling the 64x64 view, lit from the eye: coherence 1", {}, 0, "",
               [](int, std::uint64_t) { return makeFill(); }});
        b.add({"pair", "a big mirror sphere reflecting a small one, the paper's Figure 2", {}, 0, "",
               [](int, std::uint64_t) { return makePair(); }});
        b.add({"trio", "the pair with a third sphere in the hull between them: Figure 2's potential blocker", {}, 0, "",
               [](int, std::uint64_t) { return makeTrio(); }});
        return b;
    }();
    return r;
}
// [scene-registry]

Scene makeBuiltin(const std::string& spec, std::uint64_t seed) {
    if (const BuiltinInfo* b = builtinScenes().find(spec); b && b->maxSize == 0) return b->make(0, seed);
    // A sized scene, "name:N": its entry is registered as "name:N"
    const std::string base = spec.substr(0, spec.find(':'));
    if (const BuiltinInfo* b = builtinScenes().find(base + ":N"); b && b->maxSize > 0) {
        const std::string usage = "expected " + b->name + " with N a whole number from 1 to " +
                                  std::to_string(b->maxSize) + (b->sizeNote.empty() ? "" : " (" + b->sizeNote + ")");
        if (spec == base || spec == base + ":")
            throw SceneError(spec, 0, 0, "the " + base + " scene needs a size: " + usage);
        return b->make(sizeOf(spec, base + ":", b->maxSize, base.c_str(), usage), seed);
    }
    std::string names;
    for (const BuiltinInfo& b : builtinScenes()) names += (names.empty() ? "" : ", ") + b.name;
    throw SceneError(spec, 0, 0, "unknown scene '" + spec + "': not a file, and not a built-in scene (" +
                                     names + ")");
}

Scene loadScene(const std::string& spec, std::uint64_t seed) {
    std::error_code ec;
    const bool isFile = std::filesystem::exists(spec, ec) && !std::filesystem::is_directory(spec, ec);
    if (isFile || endsWithNff(spec)) return readNffFile(spec);
    return makeBuiltin(spec, seed);
}

}  // namespace rc
