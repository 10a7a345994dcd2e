#include "analysis/beam_tree.h"

#include <algorithm>
#include <limits>

namespace rc {

namespace {
constexpr std::uint64_t kAbsent = std::numeric_limits<std::uint64_t>::max();
}

void BeamTreeBuilder::onEvent(const TraceEvent& e) {
    if (e.deferred) return;
    record(e.task.node, e.task.pixel, e.task.query.origin.object, e.task.query.origin.inside,
           e.lookup.answer.object);
}

void BeamTreeBuilder::record(int path, int pixel, int originObject, bool inside, int hitObject) {
    auto [it, fresh] = keys_.try_emplace(path);
    if (fresh) it->second.assign(std::size_t(width_) * height_, kAbsent);
    // Same origin object (and side), same hit object: the same beam
    const std::uint64_t origin = std::uint64_t(std::uint32_t(originObject + 1)) * 2 + (inside ? 1 : 0);
    it->second[pixel] = (origin << 32) | std::uint32_t(hitObject + 1);
    ++rays_;
}

void BeamTreeBuilder::merge(const BeamTreeBuilder& other, const std::vector<int>& pathMap) {
    for (const auto& [path, keys] : other.keys_) {
        auto [it, fresh] = keys_.try_emplace(pathMap.at(path));
        if (fresh) it->second.assign(keys.size(), kAbsent);
        for (std::size_t p = 0; p < keys.size(); ++p)
            if (keys[p] != kAbsent) it->second[p] = keys[p];
    }
    rays_ += other.rays_;
}

std::vector<int> BeamTreeBuilder::paths() const {
    std::vector<int> p;
    for (const auto& [path, _] : keys_) p.push_back(path);
    std::sort(p.begin(), p.end());
    return p;
}

std::vector<int> BeamTreeBuilder::labels(int path) const {
    std::vector<int> label(std::size_t(width_) * height_, -1);
    auto it = keys_.find(path);
    if (it == keys_.end()) return label;
    const std::vector<std::uint64_t>& key = it->second;
    // [beam-label]
    // Flood fill connected pixels with equal (origin, hit) keys
    int next = 0;
    std::vector<int> stack;
    for (int p = 0; p < width_ * height_; ++p) {
        if (key[p] == kAbsent || label[p] >= 0) continue;
        label[p] = next;
        stack.push_back(p);
        while (!stack.empty()) {
            const int q = stack.back();
            stack.pop_back();
            const int x = q % width_, y = q / width_;
            const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
            for (const auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= width_ || n[1] >= height_) continue;
                const int r = n[1] * width_ + n[0];
                if (label[r] < 0 && key[r] == key[p]) {
                    label[r] = next;
                    stack.push_back(r);
                }
            }
        }
        ++next;
    }
    // [beam-label]
    return label;
}

BeamTreeStats BeamTreeBuilder::build() const {
    BeamTreeStats s;
    for (const auto& [path, _] : keys_) {
        const std::vector<int> l = labels(path);
        s.nodes += l.empty() ? 0 : *std::max_element(l.begin(), l.end()) + 1;
    }
    // [coherence]
    s.averageRayTreeSize = double(rays_) / (double(width_) * height_);
    s.coherence = s.nodes > 0 ? s.averageRayTreeSize / double(s.nodes) : 0.0;
    // [coherence]
    return s;
}

}  // namespace rc
