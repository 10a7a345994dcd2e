// Tutorial 05's check: rc::BeamTreeBuilder's labels and coherence (your
// tutorials/05-beam-tree/exercise.cpp in a student build) against an independent oracle, a
// brute-force labelling of the image, on random path images (recorded ray by ray) and on
// the rays of real renders (the builder listening to the render, as `raycache render
// --coherence` does).
//
// Each run shows your builder every image in a presentation of its own (drawn from a seed:
// std::random_device, or $TUTORIAL_05_SEED to repeat a run; failures print it): flipped
// left-right, top-bottom and across its diagonal at random, the objects renumbered, the
// paths given other ids and the rays recorded in a shuffled order. The beams and the
// coherence are the image's own; your labels of every pixel are brought back to the
// image's pixels and compared with the rule's beams.
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <cstdint>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "oracles.h"
#include "tutorial_frame.h"
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

// The run's seed, said with every failure so that the run can be repeated
std::uint64_t runSeed() {
    static const std::uint64_t seed = tutorial::runSeed("TUTORIAL_05_SEED");
    return seed;
}
std::string seedNote() {
    return " [this run's presentation: TUTORIAL_05_SEED=" + std::to_string(runSeed()) + " repeats it]";
}

// How an image is shown: pixel (x, y) of the image is pixel pixel(x, y) of a shownWidth x
// shownHeight image (flipped and transposed), path k is recorded as path pathId[k], object
// j (>= 0) as object object[j]
struct Presentation {
    int width = 0, height = 0, shownWidth = 0, shownHeight = 0;
    bool flipX = false, flipY = false, transpose = false;
    std::vector<int> pathId, object;
    int pixel(int p) const {
        int x = p % width, y = p / width;
        if (flipX) x = width - 1 - x;
        if (flipY) y = height - 1 - y;
        if (transpose) std::swap(x, y);
        return y * shownWidth + x;
    }
    int shownObject(int j) const { return j < 0 ? j : object[std::size_t(j)]; }
};

template <class T>
void shuffle(std::vector<T>& v, tutorial::Random& rnd) {
    for (int k = int(v.size()) - 1; k > 0; --k) std::swap(v[std::size_t(k)], v[std::size_t(rnd.index(k + 1))]);
}

Presentation presentation(tutorial::Random& rnd, int width, int height, const std::vector<tutorial::PathImage>& paths) {
    Presentation p;
    p.width = width, p.height = height;
    p.flipX = rnd.chance(0.5), p.flipY = rnd.chance(0.5), p.transpose = rnd.chance(0.5);
    p.shownWidth = p.transpose ? height : width, p.shownHeight = p.transpose ? width : height;
    p.pathId.resize(paths.size());
    for (std::size_t k = 0; k < paths.size(); ++k) p.pathId[k] = int(k);
    shuffle(p.pathId, rnd);
    int objects = 0;
    for (const tutorial::PathImage& image : paths)
        for (const tutorial::PixelRay& r : image) objects = std::max({objects, r.origin + 1, r.hit + 1});
    // Distinct numbers among some more than there are objects
    std::vector<int> numbers(std::size_t(2 * objects + 7));
    for (std::size_t j = 0; j < numbers.size(); ++j) numbers[j] = int(j);
    shuffle(numbers, rnd);
    p.object.assign(numbers.begin(), numbers.begin() + objects);
    return p;
}

// Your builder given every present ray of every path as `shown` presents them (in a
// shuffled order); its beams and coherence, and its labels brought back to the image's
// pixels (labels[k][p], -1 where path k has no ray)
struct Yours {
    tutorial::BeamStats stats;
    std::vector<std::vector<int>> labels;
};
Yours present(const Presentation& shown, const std::vector<tutorial::PathImage>& paths, tutorial::Random& rnd) {
    rc::BeamTreeBuilder builder(shown.shownWidth, shown.shownHeight);
    std::vector<std::pair<int, int>> rays;  // (path, pixel of the image)
    for (std::size_t k = 0; k < paths.size(); ++k)
        for (int p = 0; p < shown.width * shown.height; ++p)
            if (paths[k][std::size_t(p)].present) rays.emplace_back(int(k), p);
    shuffle(rays, rnd);
    for (const auto& [k, p] : rays) {
        const tutorial::PixelRay& r = paths[std::size_t(k)][std::size_t(p)];
        builder.record(shown.pathId[std::size_t(k)], shown.pixel(p), shown.shownObject(r.origin), r.inside,
                       shown.shownObject(r.hit));
    }
    Yours out;
    const rc::BeamTreeStats s = builder.build();
    out.stats = {s.nodes, s.coherence};
    for (std::size_t k = 0; k < paths.size(); ++k) {
        const std::vector<int> image = builder.labels(shown.pathId[k]);
        std::vector<int> back(std::size_t(shown.width) * shown.height, -1);
        for (int p = 0; p < shown.width * shown.height; ++p) back[std::size_t(p)] = image[std::size_t(shown.pixel(p))];
        out.labels.push_back(std::move(back));
    }
    return out;
}

// Your labels of one path against the rule (4-neighbours with the same origin, side and
// hit are one beam): every ray labelled, 4-neighbours of one key labelled alike and of two
// keys not, each label of one key; returns how many labels the path has. Labels that join
// every pair of like 4-neighbours are the rule's beams or coarser, so when they number
// the oracle's beams (checked by the caller, over all paths) they are the rule's beams.
long checkLabels(int width, int height, const tutorial::PathImage& image, const std::vector<int>& label,
                 const std::string& what) {
    auto same = [](const tutorial::PixelRay& a, const tutorial::PixelRay& b) {
        return a.origin == b.origin && a.inside == b.inside && a.hit == b.hit;
    };
    auto at = [width](int p) {
        std::ostringstream out;
        out << '(' << p % width << ", " << p / width << ')';
        return out.str();
    };
    std::string fault;  // the first pixel against the rule
    std::map<int, int> keyOf;  // a label -> the first pixel that has it
    for (int p = 0; p < width * height && fault.empty(); ++p) {
        const tutorial::PixelRay& r = image[std::size_t(p)];
        if (!r.present) continue;
        if (label[std::size_t(p)] < 0) {
            fault = "pixel " + at(p) + " has a ray but your labels() gives it none";
            break;
        }
        const int x = p % width, y = p / width;
        for (const int q : {x + 1 < width ? p + 1 : -1, y + 1 < height ? p + width : -1}) {
            if (q < 0 || !image[std::size_t(q)].present) continue;
            const bool one = same(r, image[std::size_t(q)]), yours = label[std::size_t(p)] == label[std::size_t(q)];
            if (one != yours)
                fault = "pixels " + at(p) + " and " + at(q) +
                        (one ? ": the same origin, side and hit, one beam, but your labels differ"
                             : ": another origin, side or hit, two beams, but your labels are one");
        }
        const auto [it, fresh] = keyOf.try_emplace(label[std::size_t(p)], p);
        if (fault.empty() && !fresh && !same(r, image[std::size_t(it->second)]))
            fault = "your label " + std::to_string(label[std::size_t(p)]) + " covers pixels " + at(it->second) +
                    " and " + at(p) + ", rays of another origin, side or hit";
    }
    INFO(what << ": " << fault << " (pixels of the image as recorded, before the presentation)" << seedNote());
    REQUIRE(fault.empty());
    return long(keyOf.size());
}

// The rule's labels (the oracle's) and yours are one partition of the path's rays
void samePartition(int width, int height, const tutorial::PathImage& image, const std::vector<int>& rule,
                   const std::vector<int>& label, const std::string& what) {
    std::map<int, int> toYours, toRule;
    int fault = -1;
    for (int p = 0; p < width * height && fault < 0; ++p) {
        if (!image[std::size_t(p)].present) continue;
        const auto a = toYours.try_emplace(rule[std::size_t(p)], label[std::size_t(p)]).first;
        const auto b = toRule.try_emplace(label[std::size_t(p)], rule[std::size_t(p)]).first;
        if (a->second != label[std::size_t(p)] || b->second != rule[std::size_t(p)]) fault = p;
    }
    INFO(what << ", pixel (" << fault % width << ", " << fault / width << "): the rule's beam of this pixel and "
              << "your label of it are not one and the same set of pixels" << seedNote());
    REQUIRE(fault < 0);
}

// Your builder, shown the image in this run's presentation, against the oracle: the beams,
// the coherence and every pixel's label
tutorial::BeamStats compare(int width, int height, const std::vector<tutorial::PathImage>& paths, std::uint64_t index,
                            const std::string& what) {
    tutorial::Random rnd(rc::mixKey(runSeed(), index));
    const Presentation shown = presentation(rnd, width, height, paths);
    const Yours yours = present(shown, paths, rnd);
    const Oracle want = oracle(width, height, paths);
    INFO(std::setprecision(17) << what << ": beams: the oracle's " << want.beams << ", yours " << yours.stats.beams
                               << "; coherence: the oracle's " << want.coherence << ", yours "
                               << yours.stats.coherence << seedNote());
    REQUIRE(yours.stats.beams == want.beams);
    REQUIRE(std::abs(yours.stats.coherence - want.coherence) <= 1e-12 * want.coherence);
    long labels = 0;
    for (std::size_t k = 0; k < paths.size(); ++k)
        labels += checkLabels(width, height, paths[k], yours.labels[k], what + ", path " + std::to_string(k));
    INFO("your labels() number " << labels << " beams in all");
    REQUIRE(labels == want.beams);
    return yours.stats;
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
        compare(width, height, paths, std::uint64_t(i),
                "image " + std::to_string(i) + " (" + std::to_string(width) + "x" + std::to_string(height) + ", " +
                    std::to_string(npaths) + " paths)");
    }
}

TEST_CASE("the beam tree agrees with a brute-force labelling on real renders", "[tutorial05]") {
    std::uint64_t index = 1000;
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
        const std::vector<tutorial::PathImage> paths = recorder.paths();
        const Oracle want = oracle(o.width, o.height, paths);
        const std::string path = std::string(name) == "cube:3" ? drawBeams(o.width, o.height, paths) : std::string();
        INFO("scene " << name << (path.empty() ? "" : "; your beams of cube:3: " + path));
        compare(o.width, o.height, paths, index++, std::string("scene ") + name);
        if (std::string(name) == "cube:3") {
            // The rule's own labels of the eye rays and their reflections, against yours
            tutorial::Random rnd(rc::mixKey(runSeed(), index++));
            const Presentation shown = presentation(rnd, o.width, o.height, paths);
            const Yours yours = present(shown, paths, rnd);
            for (std::size_t k = 0; k < std::min<std::size_t>(2, paths.size()); ++k)
                samePartition(o.width, o.height, paths[k], oracleLabels(o.width, o.height, paths[k]), yours.labels[k],
                              std::string("scene cube:3, path ") + std::to_string(k));
        }
        const rc::BeamTreeStats render = heard.build();
        INFO(std::setprecision(17) << "the builder that heard the render: " << render.nodes << " beams, coherence "
                                   << render.coherence);
        REQUIRE(render.nodes == want.beams);
        REQUIRE(std::abs(render.coherence - want.coherence) <= 1e-12 * want.coherence);
    }
}
