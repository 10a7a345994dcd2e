// Tutorial 05's check: tutorial::beamTree against the library's rc::BeamTreeBuilder, on
// random path images and on the rays of real renders.
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include <catch2/catch.hpp>

#include "analysis/beam_tree.h"
#include "exercise.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "tutorial_random.h"

namespace {

// Feeds the same rays to the library's beam tree
rc::BeamTreeStats library(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    rc::BeamTreeBuilder b(width, height);
    for (int path = 0; path < int(paths.size()); ++path)
        for (int p = 0; p < width * height; ++p)
            if (paths[path][p].present)
                b.record(path, p, paths[path][p].origin, paths[path][p].inside, paths[path][p].hit);
    return b.build();
}

void compare(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    const rc::BeamTreeStats want = library(width, height, paths);
    const tutorial::BeamStats got = tutorial::beamTree(width, height, paths);
    REQUIRE(got.beams == want.nodes);
    REQUIRE(std::abs(got.coherence - want.coherence) <= 1e-12 * want.coherence);
}

// Records, per ray-tree path, every pixel's ray of a render
class PathRecorder final : public rc::TraceSink {
public:
    PathRecorder(int width, int height) : pixels_(std::size_t(width) * height) {}
    void onEvent(const rc::TraceEvent& e) override {
        if (e.deferred) return;
        auto [it, fresh] = byPath_.try_emplace(e.task.node);
        if (fresh) it->second.resize(pixels_);
        const rc::RayOrigin& o = e.task.query.origin;
        it->second[e.task.pixel] = {true, o.object, o.inside, e.lookup.answer.object};
    }
    std::vector<tutorial::PathImage> paths() const {
        std::vector<tutorial::PathImage> out;
        for (const auto& [path, image] : byPath_) out.push_back(image);
        return out;
    }

private:
    std::size_t pixels_;
    std::map<int, tutorial::PathImage> byPath_;
};

}  // namespace

TEST_CASE("beamTree agrees with rc::BeamTreeBuilder on random path images", "[tutorial05]") {
    tutorial::Random rnd(1984);  // Heckbert and Hanrahan's beam tracing
    for (int i = 0; i < 300; ++i) {
        const int width = 1 + rnd.index(30), height = 1 + rnd.index(30);
        const int npaths = 1 + rnd.index(5);
        std::vector<tutorial::PathImage> paths(npaths, tutorial::PathImage(std::size_t(width) * height));
        for (tutorial::PathImage& path : paths) {
            // Rays present in a random blob; few distinct objects so that beams form
            const double cx = rnd.uniform(0, width), cy = rnd.uniform(0, height), r = rnd.uniform(1, width);
            const int objects = 1 + rnd.index(4);
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    if ((x - cx) * (x - cx) + (y - cy) * (y - cy) > r * r && &path != &paths[0]) continue;
                    tutorial::PixelRay& ray = path[std::size_t(y) * width + x];
                    ray.present = true;
                    ray.origin = rnd.chance(0.9) ? (x * objects / width) - 1 : rnd.index(objects);
                    ray.inside = rnd.chance(0.05);
                    ray.hit = rnd.chance(0.9) ? (y * objects / height) - 1 : rnd.index(objects) - 1;
                }
        }
        INFO("image " << i << " (" << width << "x" << height << ", " << npaths << " paths)");
        compare(width, height, paths);
    }
}

TEST_CASE("beamTree agrees with rc::BeamTreeBuilder on real renders", "[tutorial05]") {
    for (const char* name : {"cube:3", "pair", "glass"}) {
        auto scene = std::make_shared<const rc::Scene>(rc::makeBuiltin(name));
        rc::RenderOptions o;
        o.width = o.height = 40;
        rc::RenderSession session(scene, o);
        PathRecorder recorder(o.width, o.height);
        rc::BeamTreeBuilder builder(o.width, o.height);
        session.addSink(&recorder);
        session.addSink(&builder);
        session.run();
        const rc::BeamTreeStats want = builder.build();
        const tutorial::BeamStats got = tutorial::beamTree(o.width, o.height, recorder.paths());
        INFO("scene " << name);
        REQUIRE(got.beams == want.nodes);
        REQUIRE(std::abs(got.coherence - want.coherence) <= 1e-12 * want.coherence);
    }
}
