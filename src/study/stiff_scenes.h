#pragma once
/// \file
/// \brief Stiff and extreme scenes: the suite `raycache stability` runs.
///
/// The suite is the NFF files of a directory (tests/stiff in the source tree) plus a few
/// generators for cases that need arithmetic to set up: rays that graze silhouettes
/// exactly, blocker hulls that are nearly a cylinder or nearly degenerate, every
/// coordinate of a cube of spheres offset by 1e7, radii spanning four decades.
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rc {

/// One scene of the suite.
struct StiffScene {
    std::string name;         ///< file stem or generator name (`gen:...`)
    std::string description;  ///< what makes it stiff
    std::shared_ptr<const Scene> scene;
};

/// The generators' names (`gen:grazing`, ...), each with its description.
std::vector<std::pair<std::string, std::string>> stiffGenerators();

/// Builds the generated scene `name` (as stiffGenerators() lists it); at most 64x64.
/// \throws SceneError for an unknown name.
Scene makeStiffScene(const std::string& name);

/// The generated scenes, then every `*.nff` file of `dir` in name order (none when `dir`
/// is empty). The description of a file is its first comment line.
/// \throws SceneError when a file cannot be read.
std::vector<StiffScene> loadStiffSuite(const std::string& dir);

/// The suite directory: the environment's RAYCACHE_STIFF_DIR, else the one CMake was
/// configured with (RAYCACHE_STIFF_DIR, by default tests/stiff of the source tree); ""
/// when it is not there.
std::string defaultStiffSuiteDir();

}  // namespace rc
