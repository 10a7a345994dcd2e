// The beam tree counted a second way, apart from the library (the instructor's: the student
// edition leaves tests/instructor/ out, scripts/student_edition.py).
#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "analysis/beam_tree.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "scene/nff_reader.h"

using namespace rc;

namespace {
/// The beam tree counted a second way: a dense key image per ray-tree path (what the
/// builder kept before it stored only the rays), labelled by brute force as the tutorials'
/// oracles do (every present pixel starts with its own label; sweep after sweep each takes
/// the least label of its 4-neighbours with the same key, until none changes), not by a
/// fill or union-find. A labelling answers tutorial 05 too, so the student edition leaves
/// this folder out.
class DenseBeamCount final : public TraceSink {
public:
    DenseBeamCount(int width, int height) : width_(width), height_(height) {}
    void onEvent(const TraceEvent& e) override {
        if (e.deferred) return;
        auto [it, fresh] = keys_.try_emplace(e.task.node);
        if (fresh) it->second.assign(std::size_t(width_) * height_, kAbsent);
        const auto& o = e.task.query.origin;
        it->second[e.task.pixel] = {o.object, o.inside, e.lookup.answer().object};
    }
    std::int64_t nodes() const {
        std::int64_t n = 0;
        for (const auto& [path, key] : keys_) {
            std::vector<int> label(key.size());
            for (std::size_t p = 0; p < key.size(); ++p) label[p] = int(p);
            for (bool changed = true; changed;) {
                changed = false;
                for (int p = 0; p < width_ * height_; ++p) {
                    if (key[p] == kAbsent) continue;
                    const int x = p % width_, y = p / width_;
                    for (const int q : {x > 0 ? p - 1 : -1, x + 1 < width_ ? p + 1 : -1, y > 0 ? p - width_ : -1,
                                        y + 1 < height_ ? p + width_ : -1})
                        if (q >= 0 && key[q] == key[p] && label[q] < label[p]) label[p] = label[q], changed = true;
                }
            }
            for (std::size_t p = 0; p < key.size(); ++p) n += key[p] != kAbsent && label[p] == int(p);
        }
        return n;
    }
    std::size_t paths() const { return keys_.size(); }

private:
    using Key = std::tuple<int, bool, int>;  // origin object, inside, hit object
    static constexpr Key kAbsent{-2, false, -2};
    int width_, height_;
    std::map<int, std::vector<Key>> keys_;
};
}  // namespace

TEST_CASE("the beam tree counts what a dense per-path image counts (cube:5, glass, balls2)", "[beam]") {
    const std::string balls2 = std::string(RAYCACHE_SCENES_DIR) + "/balls2.nff";
    const std::pair<std::shared_ptr<const Scene>, int> cases[] = {
        {std::make_shared<const Scene>(makeBuiltin("cube:5")), 5},
        {std::make_shared<const Scene>(makeBuiltin("glass")), 10},
        {std::make_shared<const Scene>(readNffFile(balls2)), 5},
    };
    for (const auto& [scene, depth] : cases) {
        INFO(scene->name);
        RenderOptions o;
        o.width = 40;
        o.height = 32;
        o.shading.maxDepth = depth;
        RenderSession s(scene, o);
        BeamTreeBuilder sparse(o.width, o.height);
        DenseBeamCount dense(o.width, o.height);
        s.addSink(&sparse);
        s.addSink(&dense);
        s.run();
        const BeamTreeStats stats = sparse.build();
        REQUIRE(stats.nodes == dense.nodes());
        REQUIRE(sparse.paths().size() == dense.paths());
        // it holds the rays, one each, not an image per path
        REQUIRE(sparse.storedRays() == std::int64_t(s.counters().totalRays()));
        REQUIRE(stats.averageRayTreeSize == double(s.counters().totalRays()) / (o.width * o.height));
        REQUIRE(stats.nodes > std::int64_t(sparse.paths().size()));  // more than one beam per path somewhere
    }
}

