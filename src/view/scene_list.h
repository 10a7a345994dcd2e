#pragma once
/// \file
/// \brief The Scene menu of both front ends: the built-in scenes (those named `...:N` in the
/// sizes the core suggests), then every NFF file of a folder. The Qt GUI lists the project's
/// scenes/ folder, the page the copy it carries (/scenes). RayCache's own addition.
#include <string>
#include <vector>

namespace rc {

/// One entry of the Scene menu.
struct SceneChoice {
    std::string spec;         ///< what loadScene() takes: "cube:4", or the file's path
    std::string label;        ///< what the menu shows: "cube:4", or the file's name
    std::string description;  ///< a built-in's line, or the file's path
    bool file = false;        ///< an NFF file of `folder`
};

/// The built-in scenes (rc::builtinScenes, `:N` expanded to its sizes), then the `.nff` files
/// of `folder` by name (none when it is empty or cannot be read).
std::vector<SceneChoice> sceneChoices(const std::string& folder);

}  // namespace rc
