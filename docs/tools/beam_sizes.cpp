// The sizes of the beams of one render, for the docs' Table 1 page: how many rays each beam
// of each ray-tree depth holds. A docs tool, not part of the raycache tool.
//
// usage: beam_sizes SCENE WIDTH HEIGHT DEPTH
// prints CSV: depth,beams,rays,then for each size class "1", "2-3", "4-15", "16-63",
// "64-255", "256+" the beams of that size and the rays they hold.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s SCENE WIDTH HEIGHT DEPTH\n", argv[0]);
        return 2;
    }
    auto scene = std::make_shared<const rc::Scene>(rc::loadScene(argv[1]));
    rc::RenderOptions o;
    o.width = std::atoi(argv[2]);
    o.height = std::atoi(argv[3]);
    o.shading.maxDepth = std::atoi(argv[4]);
    rc::RenderSession session(scene, o);
    rc::BeamTreeBuilder builder(o.width, o.height);
    session.addSink(&builder);
    session.run();

    constexpr std::array<long, 6> lower{1, 2, 4, 16, 64, 256};
    struct Row {
        long beams = 0, rays = 0;
        std::array<long, 6> beamsOf{}, raysOf{};
    };
    std::map<int, Row> byDepth;
    for (int path : builder.paths()) {
        const std::vector<int> labels = builder.labels(path);
        std::vector<long> size;
        for (int l : labels)
            if (l >= 0) {
                if (std::size_t(l) >= size.size()) size.resize(std::size_t(l) + 1, 0);
                ++size[std::size_t(l)];
            }
        Row& row = byDepth[session.cacheTree().node(path).depth];
        for (long s : size) {
            std::size_t k = lower.size() - 1;
            while (s < lower[k]) --k;
            ++row.beams;
            row.rays += s;
            ++row.beamsOf[k];
            row.raysOf[k] += s;
        }
    }
    std::printf("depth,beams,rays");
    for (const char* name : {"1", "2-3", "4-15", "16-63", "64-255", "256+"})
        std::printf(",beams %s,rays %s", name, name);
    std::printf("\n");
    for (const auto& [depth, row] : byDepth) {
        std::printf("%d,%ld,%ld", depth, row.beams, row.rays);
        for (std::size_t k = 0; k < lower.size(); ++k) std::printf(",%ld,%ld", row.beamsOf[k], row.raysOf[k]);
        std::printf("\n");
    }
    return 0;
}
