#include "view/scene_list.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "scene/builtin_scenes.h"

namespace rc {

std::vector<SceneChoice> sceneChoices(const std::string& folder) {
    std::vector<SceneChoice> out;
    for (const BuiltinInfo& b : builtinScenes()) {
        const auto n = b.name.find(":N");
        if (n == std::string::npos) {
            out.push_back({b.name, b.name, b.description});
            continue;
        }
        for (int size : b.sizes) {
            const std::string spec = b.name.substr(0, n) + ":" + std::to_string(size);
            out.push_back({spec, spec, b.description});
        }
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    if (folder.empty() || !fs::is_directory(folder, ec)) return out;
    std::vector<SceneChoice> files;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext != ".nff" || !e.is_regular_file(ec)) continue;
        files.push_back({e.path().string(), e.path().filename().string(), e.path().string(), true});
    }
    std::sort(files.begin(), files.end(), [](const SceneChoice& a, const SceneChoice& b) { return a.label < b.label; });
    out.insert(out.end(), files.begin(), files.end());
    return out;
}

}  // namespace rc
