#include "analysis/beam_tree.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <new>
#include <stdexcept>

#if __has_include(<sys/mman.h>)
#include <sys/mman.h>
#endif

namespace rc {

void BeamTreeBuilder::onEvent(const TraceEvent& e) {
    if (e.deferred) return;
    record(e.task.node, e.task.pixel, e.task.query.origin.object, e.task.query.origin.inside,
           e.lookup.answer().object);
}

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kFirstBlock = 16;         // rays: 192 bytes
constexpr std::size_t kLargestSmallBlock = 4096;  // rays: 48 KB
}

BeamTreeBuilder::Block::Block(std::size_t n) : capacity(n) {
    // A block as large as a huge page is asked for as one: the kernel then clears and maps
    // it in one go, not in 512 faults
    std::size_t bytes = n * sizeof(Ray);
    void* p = nullptr;
    if (bytes >= kHugePage / 2) {
        bytes = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        p = std::aligned_alloc(kHugePage, bytes);
#ifdef MADV_HUGEPAGE
        if (p) madvise(p, bytes, MADV_HUGEPAGE);
#endif
    } else {
        p = std::malloc(bytes);
    }
    if (!p) throw std::bad_alloc();
    rays.reset(static_cast<Ray*>(p));
}

void BeamTreeBuilder::Block::Free::operator()(Ray* p) const { std::free(p); }

void BeamTreeBuilder::PathLog::grow() {
    // Small blocks, each twice the last, then huge pages. Most paths hold a few rays, and a
    // render may have hundreds of thousands of paths (distributed ray tracing with many
    // samples a pixel, soft shadows and gloss): a large first block for each would take
    // gigabytes
    seal();
    const std::size_t last = blocks.empty() ? 0 : blocks.back().capacity;
    blocks.emplace_back(last == 0                    ? kFirstBlock
                        : last < kLargestSmallBlock ? 2 * last
                                                    : kHugePage / sizeof(Ray));
    open();
}

void BeamTreeBuilder::PathLog::open() {
    if (blocks.empty()) {
        next = end = nullptr;
        return;
    }
    Block& b = blocks.back();
    next = b.rays.get() + b.size;
    end = b.rays.get() + b.capacity;
}

void BeamTreeBuilder::PathLog::resize(std::size_t n) {
    seal();
    std::size_t kept = 0, b = 0;
    for (; b < blocks.size() && kept + blocks[b].size <= n; ++b) kept += blocks[b].size;
    if (b < blocks.size()) {
        blocks[b].size = n - kept;
        blocks.erase(blocks.begin() + std::ptrdiff_t(n > kept ? b + 1 : b), blocks.end());
    }
    open();
}

std::size_t BeamTreeBuilder::PathLog::size() const {
    std::size_t n = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) n += filled(b);
    return n;
}

std::int64_t BeamTreeBuilder::reservedRays() const {
    std::int64_t n = 0;
    for (const PathLog& log : rays_by_path_)
        for (const Block& b : log.blocks) n += std::int64_t(b.capacity);
    return n;
}

void BeamTreeBuilder::PathLog::append(PathLog&& other) {
    // Blocks move whole (their rays stay where they are); the next ray goes into the room
    // left in the last one, after the other's rays
    seal();
    other.seal();
    for (Block& b : other.blocks) blocks.push_back(std::move(b));
    other = PathLog{};
    open();
}

void BeamTreeBuilder::record(int path, int pixel, int originObject, bool inside, int hitObject) {
    // Same origin object (and side), same hit object: the same beam
    const std::uint32_t origin = std::uint32_t(originObject + 1) * 2u + (inside ? 1u : 0u);
    if (std::size_t(path) >= rays_by_path_.size()) rays_by_path_.resize(std::size_t(path) + 1);
    rays_by_path_[std::size_t(path)].push_back(Ray{pixel, origin, std::uint32_t(hitObject + 1)});
    ++rays_;
}

void BeamTreeBuilder::merge(BeamTreeBuilder&& other, const std::vector<int>& pathMap) {
    for (std::size_t path = 0; path < other.rays_by_path_.size(); ++path) {
        if (other.rays_by_path_[path].blocks.empty()) continue;
        const std::size_t to = std::size_t(pathMap.at(path));
        if (to >= rays_by_path_.size()) rays_by_path_.resize(to + 1);
        rays_by_path_[to].append(std::move(other.rays_by_path_[path]));
    }
    rays_ += other.rays_;
    other.rays_ = 0;
}

std::vector<int> BeamTreeBuilder::paths() const {
    std::vector<int> p;
    for (std::size_t path = 0; path < rays_by_path_.size(); ++path)
        if (!rays_by_path_[path].blocks.empty()) p.push_back(int(path));
    return p;
}

std::vector<BeamTreeBuilder::Ray> BeamTreeBuilder::byPixel(const PathLog& rays) {
    std::vector<Ray> sorted;
    sorted.reserve(rays.size());
    for (std::size_t b = 0; b < rays.blocks.size(); ++b)
        sorted.insert(sorted.end(), rays.blocks[b].begin(), rays.blocks[b].begin() + rays.filled(b));
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

// labelBeams() and build(): analysis/beam_labels.cpp (tutorial 05's hole)

std::vector<int> BeamTreeBuilder::labels(int path) const {
    std::vector<int> image(std::size_t(width_) * height_, -1);
    if (path < 0 || std::size_t(path) >= rays_by_path_.size()) return image;
    const std::vector<Ray> rays = byPixel(rays_by_path_[std::size_t(path)]);
    std::vector<int> label;
    labelBeams(rays, image, label);
    for (std::size_t i = 0; i < rays.size(); ++i) image[std::size_t(rays[i].pixel)] = label[i];
    return image;
}

BeamTreeBuilder::Mark BeamTreeBuilder::mark() const {
    Mark m;
    m.rays = rays_;
    for (std::size_t path = 0; path < rays_by_path_.size(); ++path)
        if (!rays_by_path_[path].blocks.empty()) m.paths.emplace_back(int(path), rays_by_path_[path].size());
    return m;
}

void BeamTreeBuilder::rollback(const Mark& m) {
    std::vector<std::size_t> keep(rays_by_path_.size(), 0);
    for (const auto& [path, size] : m.paths) {
        if (path < 0 || std::size_t(path) >= rays_by_path_.size() || rays_by_path_[std::size_t(path)].size() < size)
            throw std::invalid_argument("BeamTreeBuilder::rollback: a mark of another builder");
        keep[std::size_t(path)] = size;
    }
    for (std::size_t path = 0; path < rays_by_path_.size(); ++path) rays_by_path_[path].resize(keep[path]);
    rays_ = m.rays;
}

}  // namespace rc
