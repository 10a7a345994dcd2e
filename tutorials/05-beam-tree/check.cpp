// Tutorial 05's check: rc::BeamTreeBuilder's labels and coherence (your
// tutorials/05-beam-tree/exercise.cpp in a student build) against an independent oracle, a
// brute-force labelling of the image, on random path images (recorded ray by ray) and on
// the rays of real renders (the builder listening to the render, as `raycache render
// --coherence` does).
#include <iomanip>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <cstdint>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "oracles.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace tutorial {

/// rc::BeamTreeBuilder given every present ray of every path, path k recorded as path k
BeamStats beamTree(int width, int height, const std::vector<PathImage>& paths) {
    rc::BeamTreeBuilder builder(width, height);
    for (std::size_t k = 0; k < paths.size(); ++k)
        for (int p = 0; p < width * height; ++p) {
            const PixelRay& r = paths[k][std::size_t(p)];
            if (r.present) builder.record(int(k), p, r.origin, r.inside, r.hit);
        }
    const rc::BeamTreeStats s = builder.build();
    return {s.nodes, s.coherence};
}

}  // namespace tutorial

namespace {

// The oracle's beams (data: oracles.h, oracle_data.txt)
using Oracle = tutorial::BeamStats;
Oracle oracle(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    return tutorial::oracleBeams(width, height, paths);
}
using tutorial::oracleLabels;

void compare(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    const Oracle want = oracle(width, height, paths);
    const tutorial::BeamStats got = tutorial::beamTree(width, height, paths);
    INFO(std::setprecision(17) << "beams: the oracle's " << want.beams << ", yours " << got.beams
                               << "; coherence: the oracle's " << want.coherence << ", yours " << got.coherence);
    REQUIRE(got.beams == want.beams);
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
        it->second[e.task.pixel] = {true, o.object, o.inside, e.lookup.answer().object};
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

// The picture: the beams of the first two ray-tree paths, each of the rule's beams (the
// oracle's labels: 4-neighbours with the same origin, side and hit) in its colour; pixels
// with no ray at that path are white. For every two neighbouring pixels the check asks
// your beamTree about an image that holds just those two rays (one beam: your code merges
// them) and marks both magenta where your answer is not the rule's: 4-neighbours merged
// exactly when they are of one beam, and no merge of diagonal neighbours that joins two beams.
std::string drawBeams(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    const int panels = std::min<int>(2, int(paths.size()));
    tutorial::Picture pic(panels * (width + 2), height, {255, 255, 255});
    long beams = 0, wrong = 0;
    for (int k = 0; k < panels; ++k) {
        const tutorial::PathImage& image = paths[k];
        const std::vector<int> rule = oracleLabels(width, height, image);
        std::vector<char> bad(image.size(), 0);
        tutorial::PathImage two(image.size());
        for (int p = 0; p < width * height; ++p) {
            const int x = p % width, y = p / width;
            // Right and down neighbours, and the two diagonal ones (never one beam alone)
            const int right = x + 1 < width ? p + 1 : -1, down = y + 1 < height ? p + width : -1;
            for (const int q : {right, down, x + 1 < width && y + 1 < height ? p + width + 1 : -1,
                                x > 0 && y + 1 < height ? p + width - 1 : -1}) {
                if (q < 0 || !image[p].present || !image[q].present) continue;
                two[p] = image[p], two[q] = image[q];
                const bool yours = tutorial::beamTree(width, height, {two}).beams == 1;
                // 4-neighbours: merged exactly when the rule puts them in one beam; diagonal
                // ones: a merge matters when it joins two of the rule's beams
                const bool wrong = q == right || q == down ? yours != (rule[p] == rule[q]) : yours && rule[p] != rule[q];
                if (wrong) bad[p] = bad[q] = 1;
                two[p] = two[q] = tutorial::PixelRay{};
            }
        }
        beams += tutorial::beamTree(width, height, {image}).beams;
        for (int p = 0; p < width * height; ++p) {
            if (!image[p].present) continue;
            wrong += bad[p];
            pic.set(k * (width + 2) + p % width, p / width,
                    bad[p] ? tutorial::Rgb{255, 0, 255} : tutorial::labelColour(rule[p] % 997));
        }
    }
    const std::string path = pic.save("beams", 6);
    tutorial::announcePicture("the beams of cube:3's eye rays (left) and their reflections (right): your code finds " +
                                  std::to_string(beams) + " beams; magenta: " + std::to_string(wrong) +
                                  " pixel(s) your code merges with a neighbour against the rule, or splits from one",
                              path);
    return path;
}

}  // namespace

TEST_CASE("the beam tree agrees with a brute-force labelling on random path images", "[tutorial05]") {
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
        INFO(std::setprecision(17) << "image " << i << " (" << width << "x" << height << ", " << npaths << " paths)");
        compare(width, height, paths);
    }
}

TEST_CASE("the beam tree agrees with a brute-force labelling on real renders", "[tutorial05]") {
    for (const char* name : {"cube:3", "pair", "glass"}) {
        auto scene = std::make_shared<const rc::Scene>(rc::makeBuiltin(name));
        rc::RenderOptions o;
        o.width = o.height = 40;
        rc::RenderSession session(scene, o);
        PathRecorder recorder(o.width, o.height);
        session.addSink(&recorder);
        // The renderer's own: the builder hears the render's rays
        rc::BeamTreeBuilder heard(o.width, o.height);
        session.addSink(&heard);
        session.run();
        const Oracle want = oracle(o.width, o.height, recorder.paths());
        const tutorial::BeamStats got = tutorial::beamTree(o.width, o.height, recorder.paths());
        const std::string path =
            std::string(name) == "cube:3" ? drawBeams(o.width, o.height, recorder.paths()) : std::string();
        INFO(std::setprecision(17) << "scene " << name << ": beams: the oracle's " << want.beams << ", yours "
                                   << got.beams << "; coherence: the oracle's " << want.coherence << ", yours "
                                   << got.coherence << (path.empty() ? "" : "; your beams of cube:3: " + path));
        REQUIRE(got.beams == want.beams);
        REQUIRE(std::abs(got.coherence - want.coherence) <= 1e-12 * want.coherence);
        const rc::BeamTreeStats render = heard.build();
        INFO(std::setprecision(17) << "the builder that heard the render: " << render.nodes << " beams, coherence "
                                   << render.coherence);
        REQUIRE(render.nodes == want.beams);
        REQUIRE(std::abs(render.coherence - want.coherence) <= 1e-12 * want.coherence);
    }
}
