// The ray tree of one pixel of a real render, as a Graphviz graph, for the docs' ray-tree
// page: nodes are the surfaces the rays meet (the eye, the objects hit, a light reached,
// the background), links are the rays, each labelled with its kind and what the cache
// decided. A docs tool, not part of the raycache tool.
//
// usage: ray_tree_dot SCENE X Y CACHE    (prints the graph in dot's language)
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "trace/trace_event.h"

namespace {
// Keeps the events of one pixel, in the order they were traced
struct PixelEvents : rc::TraceSink {
    int pixel = 0;
    std::vector<rc::TraceEvent> events;
    void onEvent(const rc::TraceEvent& e) override {
        if (e.task.pixel == pixel && !e.deferred) events.push_back(e);
    }
};
}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s SCENE X Y CACHE\n", argv[0]);
        return 2;
    }
    auto scene = std::make_shared<const rc::Scene>(rc::loadScene(argv[1]));
    rc::RenderOptions o;
    o.width = scene->camera.width;
    o.height = scene->camera.height;
    const auto cache = rc::parseCacheKind(argv[4]);
    if (!cache) {
        std::fprintf(stderr, "%s: no cache '%s'\n", argv[0], argv[4]);
        return 2;
    }
    o.cache = *cache;
    PixelEvents sink;
    sink.pixel = std::atoi(argv[3]) * o.width + std::atoi(argv[2]);
    rc::RenderSession session(scene, o);
    session.addSink(&sink);
    session.run();

    // A ray's parent is the last ray of the pixel traced on its path's parent path (scanline
    // order traces a pixel's tree depth first, one ray per path and sample)
    const rc::CacheTree& tree = session.cacheTree();
    std::map<int, int> lastOnPath;  // path -> graph node of the surface its last ray reached
    std::printf("digraph ray_tree {\n  rankdir=TB; bgcolor=\"transparent\";\n"
                "  node [fontname=\"Helvetica\", fontsize=11, shape=box, style=\"rounded,filled\", fillcolor=\"#eef2f8\"];\n"
                "  edge [fontname=\"Helvetica\", fontsize=10];\n"
                "  n0 [label=\"eye\", shape=circle, fillcolor=\"#ffffff\"];\n");
    int next = 1;
    for (const rc::TraceEvent& e : sink.events) {
        const rc::Query& q = e.task.query;
        const int parentPath = tree.node(e.task.node).parent;
        const int from = parentPath < 0 ? 0 : lastOnPath.at(parentPath);
        const int to = next++;
        std::string what;
        const char* fill = "#eef2f8";
        if (q.kind == rc::RayKind::Shadow) {
            what = e.lookup.object >= 0 ? "blocked by object " + std::to_string(e.lookup.object)
                                        : "light " + std::to_string(q.light + 1) + " reached";
            fill = e.lookup.object >= 0 ? "#f4d6d6" : "#fff4c2";
        } else if (e.lookup.object >= 0) {
            what = "object " + std::to_string(e.lookup.object);
        } else {
            what = "background";
            fill = "#e4e4e4";
        }
        std::string decision(rc::toString(e.lookup.decision));
        if (e.lookup.reason != rc::MissReason::None) decision += ": " + std::string(rc::toString(e.lookup.reason));
        std::printf("  n%d [label=\"%s\", fillcolor=\"%s\"];\n", to, what.c_str(), fill);
        std::printf("  n%d -> n%d [label=\" %s\\n %s, %d test%s\"%s];\n", from, to, std::string(rc::toString(q.kind)).c_str(),
                    decision.c_str(), e.tests, e.tests == 1 ? "" : "s", q.kind == rc::RayKind::Shadow ? ", style=dashed" : "");
        lastOnPath[e.task.node] = to;
    }
    std::printf("}\n");
    return 0;
}
