#include "render/left_out.h"
#include "search/cache_registry.h"

namespace rc {

std::vector<std::string> leftOut(const Scene& scene, const RenderOptions* options, const Counters* counters) {
    std::vector<std::string> out;
    // Only the materials some object wears count
    bool reflective = false, transparent = false, lit = false;
    for (const Object& o : scene.objects) {
        const Material& m = scene.materials[o.material];
        reflective |= m.ks > 0.0 || m.kt > 0.0;  // every transmitter also reflects
        transparent |= m.kt > 0.0;
        lit |= m.kd > 0.0 || (m.ks > 0.0 && m.shine > 0.0);
    }
    if (scene.skippedCount > 0) {
        // The reader's polygons of zero area, each named (the first few)
        std::string line = "polygons of zero area: " + std::to_string(scene.skippedCount) +
                           " skipped, no ray can hit them";
        for (std::size_t i = 0; i < scene.skipped.size(); ++i) {
            const std::string& s = scene.skipped[i];
            line += (i == 0 ? " (" : ", ") + s.substr(0, s.find(": "));
        }
        if (!scene.skipped.empty())
            line += long(scene.skipped.size()) < scene.skippedCount ? ", ...)" : ")";
        out.push_back(line);
    }
    if (scene.objects.empty()) out.push_back("complete searches and secondary rays: the scene is empty");
    if (scene.lights.empty())
        out.push_back("shadow rays: no lights");
    else if (!scene.objects.empty() && !lit)
        out.push_back("shadow rays: no material has Kd > 0 or a specular highlight");
    if (options && options->shading.maxDepth <= 1) {
        out.push_back("reflection and refraction rays: depth 1 traces eye rays only");
    } else {
        if (!reflective) out.push_back("reflection rays: no material has Ks > 0 or T > 0");
        if (!transparent) out.push_back("refraction rays and interior blocker lists: no transparent objects");
    }
    if (options && counters && cacheInfo(options->cache).blockerLists) {
        // Origins: every object and the eye; targets: every object and every light
        const long long pairs =
            (long long)(scene.size() + 1) * (long long)(scene.size() + scene.lights.size());
        out.push_back("blocker lists: only for the (origin, target) pairs a ray met: " +
                      std::to_string(counters->blockerListsBuilt) + " built, " + std::to_string(pairs) +
                      " pairs possible");
    }
    return out;
}

}  // namespace rc
