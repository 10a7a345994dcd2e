#include "analysis/beam_tree.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace rc {

void BeamTreeBuilder::onEvent(const TraceEvent& e) {
    if (e.deferred) return;
    record(e.task.node, e.task.pixel, e.task.query.origin.object, e.task.query.origin.inside,
           e.lookup.answer.object);
}

void BeamTreeBuilder::record(int path, int pixel, int originObject, bool inside, int hitObject) {
    // Same origin object (and side), same hit object: the same beam
    const std::uint32_t origin = std::uint32_t(originObject + 1) * 2u + (inside ? 1u : 0u);
    rays_by_path_[path].push_back(Ray{pixel, origin, std::uint32_t(hitObject + 1)});
    ++rays_;
}

void BeamTreeBuilder::merge(const BeamTreeBuilder& other, const std::vector<int>& pathMap) {
    for (const auto& [path, rays] : other.rays_by_path_) {
        std::vector<Ray>& to = rays_by_path_[pathMap.at(path)];
        to.insert(to.end(), rays.begin(), rays.end());
    }
    rays_ += other.rays_;
}

std::vector<int> BeamTreeBuilder::paths() const {
    std::vector<int> p;
    for (const auto& [path, _] : rays_by_path_) p.push_back(path);
    std::sort(p.begin(), p.end());
    return p;
}

std::vector<BeamTreeBuilder::Ray> BeamTreeBuilder::byPixel(const std::vector<Ray>& rays) {
    std::vector<Ray> sorted = rays;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Ray& a, const Ray& b) { return a.pixel < b.pixel; });
    // Keep the last of each pixel's rays (a pixel traced again replaces its key)
    std::size_t n = 0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        if (i + 1 < sorted.size() && sorted[i + 1].pixel == sorted[i].pixel) continue;
        sorted[n++] = sorted[i];
    }
    sorted.resize(n);
    return sorted;
}

int BeamTreeBuilder::labelBeams(const std::vector<Ray>& rays, std::vector<int>& index, std::vector<int>& label) const {
    for (std::size_t i = 0; i < rays.size(); ++i) index[std::size_t(rays[i].pixel)] = int(i);
    label.assign(rays.size(), -1);
    // [beam-label]
    // Flood fill connected pixels with equal (origin, hit) keys
    int next = 0;
    std::vector<int> stack;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (label[i] >= 0) continue;
        label[i] = next;
        stack.push_back(int(i));
        while (!stack.empty()) {
            const Ray& q = rays[std::size_t(stack.back())];
            stack.pop_back();
            const int x = q.pixel % width_, y = q.pixel / width_;
            const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
            for (const auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= width_ || n[1] >= height_) continue;
                const int r = index[std::size_t(n[1]) * width_ + n[0]];
                if (r >= 0 && label[r] < 0 && rays[r].sameBeam(rays[i])) {
                    label[r] = next;
                    stack.push_back(r);
                }
            }
        }
        ++next;
    }
    // [beam-label]
    for (const Ray& r : rays) index[std::size_t(r.pixel)] = -1;
    return next;
}

std::vector<int> BeamTreeBuilder::labels(int path) const {
    std::vector<int> image(std::size_t(width_) * height_, -1);
    auto it = rays_by_path_.find(path);
    if (it == rays_by_path_.end()) return image;
    const std::vector<Ray> rays = byPixel(it->second);
    std::vector<int> label;
    labelBeams(rays, image, label);
    for (std::size_t i = 0; i < rays.size(); ++i) image[std::size_t(rays[i].pixel)] = label[i];
    return image;
}

BeamTreeStats BeamTreeBuilder::build() const {
    BeamTreeStats s;
    std::vector<int> index(std::size_t(width_) * height_, -1);
    std::vector<int> label;
    for (const auto& [path, rays] : rays_by_path_) s.nodes += labelBeams(byPixel(rays), index, label);
    // [coherence]
    s.averageRayTreeSize = double(rays_) / (double(width_) * height_);
    s.coherence = s.nodes > 0 ? s.averageRayTreeSize / double(s.nodes) : 0.0;
    // [coherence]
    return s;
}

BeamTreeBuilder::Mark BeamTreeBuilder::mark() const {
    Mark m;
    m.rays = rays_;
    for (const auto& [path, rays] : rays_by_path_) m.paths.emplace_back(path, rays.size());
    return m;
}

void BeamTreeBuilder::rollback(const Mark& m) {
    std::unordered_map<int, std::vector<Ray>> kept;
    for (const auto& [path, size] : m.paths) {
        auto it = rays_by_path_.find(path);
        if (it == rays_by_path_.end() || it->second.size() < size)
            throw std::invalid_argument("BeamTreeBuilder::rollback: a mark of another builder");
        it->second.resize(size);
        kept.emplace(path, std::move(it->second));
    }
    rays_by_path_ = std::move(kept);
    rays_ = m.rays;
}

}  // namespace rc
