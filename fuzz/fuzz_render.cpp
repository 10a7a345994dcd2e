// libFuzzer target: parse arbitrary bytes as NFF and, when that gives a scene, render it
// at 4x4 and depth 2 with every cache strategy, ray order and complete search, each
// answer checked against the plain scan (--verify). A crash, a sanitizer report (NaN
// cast to an integer, signed overflow, out-of-bounds access, ...) or a hang is a
// finding; disagreements are not (ties between equally near hits are legitimate on
// arbitrary scenes). Scenes are capped so that one input stays fast: at most 32
// primitives, 8 lights and 1024 polygon vertices in all.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "render/render_session.h"

namespace {
constexpr long kMaxPrimitives = 32;
constexpr std::size_t kMaxLights = 8;
constexpr std::size_t kMaxVertices = 1024;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = "fuzz.nff";
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::shared_ptr<const rc::Scene> scene;
    try {
        scene = std::make_shared<const rc::Scene>(rc::parseNff(text, file, kMaxPrimitives));
    } catch (const rc::SceneError& e) {
        rc::fuzz::checkError(e, file);
        return 0;
    }
    rc::fuzz::checkScene(*scene);
    if (scene->lights.size() > kMaxLights) return -1;  // too slow: keep it out of the corpus
    std::size_t vertices = 0;
    for (const rc::Polygon& p : scene->polygons) vertices += p.vertices.size();
    if (vertices > kMaxVertices) return -1;

    for (rc::CacheKind cache : {rc::CacheKind::None, rc::CacheKind::Cylinder, rc::CacheKind::Blocker})
        for (rc::OrderKind order : {rc::OrderKind::Scanline, rc::OrderKind::Progressive, rc::OrderKind::BreadthFirst})
            for (rc::AccelKind accel : {rc::AccelKind::Linear, rc::AccelKind::Grid, rc::AccelKind::Bvh}) {
                rc::RenderOptions o;
                o.width = 4;
                o.height = 4;
                o.cache = cache;
                o.order = order;
                o.accel = accel;
                o.shading.maxDepth = 2;
                o.band = 2;
                o.verify = cache != rc::CacheKind::None;
                rc::RenderSession session(scene, o);
                FUZZ_CHECK(session.run());
                const auto rgb = session.image().rgb8();
                FUZZ_CHECK(rgb.size() == 4 * 4 * 3);
                FUZZ_CHECK(session.counters().rays[int(rc::RayKind::Primary)] == 16);
            }
    return 0;
}
