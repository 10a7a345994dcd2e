#include "render/left_out.h"

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
    if (options && counters && (options->cache == CacheKind::Blocker || options->cache == CacheKind::BlockerPlus ||
                                  options->cache == CacheKind::BlockerDirections)) {
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
