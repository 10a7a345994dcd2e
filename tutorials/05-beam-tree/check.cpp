// Tutorial 05's check: rc::BeamTreeBuilder's labels and coherence (your
// tutorials/05-beam-tree/exercise.cpp in a student build) against an independent oracle, a
// brute-force labelling of the image, on random path images (recorded ray by ray) and on
// the rays of real renders (the builder listening to the render, as `raycache render
// --coherence` does).
#include <iomanip>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <cstdint>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace tutorial {

/// The ray a pixel has at one ray-tree path (eye; eye/reflection; eye/shadow 1; ...).
struct PixelRay {
    bool present = false;  ///< false: this pixel's ray tree has no ray at this path
    int origin = -1;       ///< object the ray leaves (-1: the eye)
    bool inside = false;   ///< it leaves into the object's interior (refraction)
    int hit = -1;          ///< object it hits (-1: nothing)
};

/// One ray-tree path over the whole image: `rays[y * width + x]`.
using PathImage = std::vector<PixelRay>;

/// The beam tree's size and the paper's coherence.
struct BeamStats {
    std::int64_t beams = 0;
    double coherence = 0.0;
};

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

// The oracle: brute force over the image. Every present ray starts with its own label; sweep
// after sweep, each takes the least label of its 4-neighbours with the same origin, side
// and hit, until no label changes. Then each label left is one beam.
struct Oracle {
    std::int64_t nodes = 0;
    double coherence = 0.0;
};
// The oracle's labels of one path image (each pixel's least label after the sweeps)
std::vector<int> oracleLabels(int width, int height, const tutorial::PathImage& at) {
    auto same = [&](int p, int q) {
        return at[p].present && at[q].present && at[p].origin == at[q].origin && at[p].inside == at[q].inside &&
               at[p].hit == at[q].hit;
    };
    std::vector<int> label(at.size());
    for (int p = 0; p < width * height; ++p) label[p] = p;
    for (bool changed = true; changed;) {
        changed = false;
        for (int p = 0; p < width * height; ++p) {
            if (!at[p].present) continue;
            const int x = p % width, y = p / width;
            for (int q : {x > 0 ? p - 1 : -1, x + 1 < width ? p + 1 : -1, y > 0 ? p - width : -1,
                          y + 1 < height ? p + width : -1})
                if (q >= 0 && same(p, q) && label[q] < label[p]) label[p] = label[q], changed = true;
        }
    }
    return label;
}
Oracle oracle(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    std::int64_t rays = 0, beams = 0;
    for (const tutorial::PathImage& at : paths) {
        const std::vector<int> label = oracleLabels(width, height, at);
        for (int p = 0; p < width * height; ++p) {
            rays += at[p].present;
            beams += at[p].present && label[p] == p;
        }
    }
    const double averageRayTree = double(rays) / (double(width) * height);
    return {beams, beams > 0 ? averageRayTree / double(beams) : 0.0};
}

void compare(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    const Oracle want = oracle(width, height, paths);
    const tutorial::BeamStats got = tutorial::beamTree(width, height, paths);
    INFO(std::setprecision(17) << "beams: the oracle's " << want.nodes << ", yours " << got.beams
                               << "; coherence: the oracle's " << want.coherence << ", yours " << got.coherence);
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

// The picture: the beams of the first two ray-tree paths as your beamTree labels them.
// For every two neighbouring pixels the check asks your beamTree about an image that
// holds just those two rays: one beam means your code merges them. The pieces that your
// merges make are drawn each in its colour; pixels with no ray at that path are white;
// magenta marks a beam of yours that joins two of the rule's beams or splits one.
std::string drawBeams(int width, int height, const std::vector<tutorial::PathImage>& paths) {
    const int panels = std::min<int>(2, int(paths.size()));
    tutorial::Picture pic(panels * (width + 2), height, {255, 255, 255});
    long beams = 0;
    for (int k = 0; k < panels; ++k) {
        const tutorial::PathImage& image = paths[k];
        // Two partitions of the pixels: the one your merges make, and the rule's (the oracle's
        // labels: 4-neighbours with the same origin, side and hit)
        std::vector<int> parent(image.size());
        std::iota(parent.begin(), parent.end(), 0);
        const std::vector<int> rule = oracleLabels(width, height, image);
        auto find = [](std::vector<int>& up, int p) {
            while (up[p] != p) p = up[p] = up[up[p]];
            return p;
        };
        tutorial::PathImage two(image.size());
        for (int p = 0; p < width * height; ++p) {
            const int x = p % width, y = p / width;
            // Right and down neighbours, and the two diagonal ones (never one beam alone)
            for (const int q : {x + 1 < width ? p + 1 : -1, y + 1 < height ? p + width : -1,
                                x + 1 < width && y + 1 < height ? p + width + 1 : -1,
                                x > 0 && y + 1 < height ? p + width - 1 : -1}) {
                if (q < 0 || !image[p].present || !image[q].present) continue;
                two[p] = image[p], two[q] = image[q];
                if (tutorial::beamTree(width, height, {two}).beams == 1) parent[find(parent, p)] = find(parent, q);
                two[p] = two[q] = tutorial::PixelRay{};
            }
        }
        // A beam of yours that joins two of the rule's, or a beam of the rule's you split: magenta
        std::vector<int> ruleOf(image.size(), -1), yoursOf(image.size(), -1);
        std::vector<char> bad(image.size(), 0);
        for (int p = 0; p < width * height; ++p) {
            if (!image[p].present) continue;
            const int a = find(parent, p), b = rule[p];
            if (ruleOf[a] < 0) ruleOf[a] = b;
            if (yoursOf[b] < 0) yoursOf[b] = a;
            if (ruleOf[a] != b) bad[a] = 1;
            if (yoursOf[b] != a) bad[a] = bad[yoursOf[b]] = 1;
        }
        for (int p = 0; p < width * height; ++p) {
            if (!image[p].present) continue;
            const int a = find(parent, p);
            beams += a == p;
            pic.set(k * (width + 2) + p % width, p / width,
                    bad[a] ? tutorial::Rgb{255, 0, 255} : tutorial::labelColour(a % 997));
        }
    }
    const std::string path = pic.save("beams", 6);
    tutorial::announcePicture("the beams of cube:3's eye rays (left) and their reflections (right), as your code merges "
                              "neighbours: " + std::to_string(beams) + " beams; magenta: merged or split against the rule",
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
        INFO(std::setprecision(17) << "scene " << name << ": beams: the oracle's " << want.nodes << ", yours "
                                   << got.beams << "; coherence: the oracle's " << want.coherence << ", yours "
                                   << got.coherence << (path.empty() ? "" : "; your beams of cube:3: " + path));
        REQUIRE(got.beams == want.nodes);
        REQUIRE(std::abs(got.coherence - want.coherence) <= 1e-12 * want.coherence);
        const rc::BeamTreeStats render = heard.build();
        INFO(std::setprecision(17) << "the builder that heard the render: " << render.nodes << " beams, coherence "
                                   << render.coherence);
        REQUIRE(render.nodes == want.nodes);
        REQUIRE(std::abs(render.coherence - want.coherence) <= 1e-12 * want.coherence);
    }
}
