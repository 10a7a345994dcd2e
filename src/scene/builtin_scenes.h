#pragma once
/// \file
/// \brief Built-in scene generators (`cube:N`, `balls:N`, `glass`, `fill`, `pair`, `trio`) and
/// loadScene().
///
/// The generators are deterministic across machines and compilers: random numbers come
/// from std::mt19937_64 and are turned into doubles by hand, never through the
/// implementation-defined std::uniform_real_distribution.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/registry.h"
#include "scene/scene.h"

namespace rc {

/// A built-in scene's name as the command line takes it (e.g. "cube:N"), one line that
/// describes it, and what makes it.
struct BuiltinInfo {
    std::string name;
    std::string description;
    /// For a name ending in ":N": a few sizes worth offering in a menu, smallest first.
    std::vector<int> sizes;
    int maxSize = 0;        ///< the largest N of a name ending in ":N"; 0 for a scene without a size
    std::string sizeNote;   ///< what the largest N means, for the message about a bad N ("" for none)
    /// Builds the scene of size `n` (0 for one without a size) with `seed`.
    std::function<Scene(int n, std::uint64_t seed)> make;
};

/// Every built-in scene, in the order `raycache scenes` lists them; a new one is one entry
/// in builtin_scenes.cpp, and the CLI, the GUI's and the page's scene menus list it.
const Registry<BuiltinInfo>& builtinScenes();

/// Builds the built-in scene named by `spec`:
/// - `cube:N` (1 <= N <= 64): RayCache's reconstruction of the paper's Table 1 scene (the
///   lattice is the paper's; jitter, radii, lights, materials, view and depth are
///   RayCache's), N^3 jittered reflective spheres on a lattice, seen from a corner so that the cube fills the view; 512x512.
/// - `balls:N` (1 <= N <= kMaxSphereflake): SPD's sphereflake of size N, as
///   `balls -s N -c -r 0` prints it (makeSphereflake()); 1 + 9 + ... + 9^N spheres
///   (SPD's default size 4: 7,381) on a ground square; 512x512. Does not depend on `seed`.
/// - `glass`: refracting spheres in front of and among opaque ones on a ground square,
///   with a few seed-placed marbles; 512x512.
/// - `fill`: one diffuse sphere that every eye ray hits, lit from next to the eye, so
///   that the coherence is 1; 64x64. Does not depend on `seed`.
/// - `pair`: a big mirror sphere and a small sphere whose reflection it shows (the
///   paper's Figure 2); 256x256. Does not depend on `seed`.
/// - `trio`: `pair` with a third, small sphere inside the hull between the two (the
///   potential blocker of the paper's Figure 2); 256x256. Does not depend on `seed`.
/// Scene::name is the canonical spec ("cube:8", "glass", ...).
/// \throws SceneError(spec, 0, 0, message) for an unknown name or a bad N.
Scene makeBuiltin(const std::string& spec, std::uint64_t seed = 1986);

/// An existing file, or a spec ending in ".nff", is read with readNffFile(); anything
/// else goes to makeBuiltin().
/// \throws SceneError
Scene loadScene(const std::string& spec, std::uint64_t seed = 1986);

}  // namespace rc
