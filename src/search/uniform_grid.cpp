#include "search/uniform_grid.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "search/object_test.h"

namespace rc {

namespace {
/// The cell of a coordinate measured in cells, clamped to [0, res - 1] before it is
/// converted: a far point (a light at 1e100) or NaN would overflow int (undefined).
int clampedCell(double x, int res) {
    if (!(x >= 0.0)) return 0;
    if (x >= double(res - 1)) return res - 1;
    return int(x);  // floor, as x >= 0
}
}  // namespace

UniformGrid::UniformGrid(const Scene& scene, double density) : CompleteSearch(scene), mailbox_(scene.size(), 0) {
    if (scene.size() == 0) {
        cellStart_.assign(2, 0);
        return;
    }
    lo_ = Vec3(kNoHit);
    hi_ = Vec3(-kNoHit);
    for (const Object& o : scene.objects) {
        lo_ = glm::min(lo_, o.bound.c - Vec3(o.bound.r));
        hi_ = glm::max(hi_, o.bound.c + Vec3(o.bound.r));
    }
    // Widen by a hair so rounding in the walk never loses an object at a cell boundary
    const Vec3 ext = hi_ - lo_;
    const double pad = 1e-9 * (glm::length(ext) + glm::length(lo_) + glm::length(hi_)) + 1e-300;
    lo_ -= Vec3(pad);
    hi_ += Vec3(pad);
    const Vec3 size = hi_ - lo_;
    // A flat or coincident scene has (almost) no volume: each side counts at least a
    // millionth of the longest, so the cells stay boxes instead of slivers
    const double longest = std::max(size.x, std::max(size.y, size.z));
    double volume = 1.0;
    for (int a = 0; a < 3; ++a) volume *= std::max(size[a], 1e-6 * longest);
    volume = std::max(volume, 1e-300);
    const double n = double(scene.size());
    const double cellsWanted = std::clamp(density * n, 1.0, double(kMaxCells));
    const double side = std::cbrt(volume / cellsWanted);
    for (int a = 0; a < 3; ++a) res_[a] = 1 + clampedCell(std::ceil(size[a] / side) - 1.0, 128);

    // [grid-caps]
    // Count the references each resolution would hold (in 64 bits: no product wraps); where
    // the objects overlap too much for it, halve the resolution until they fit
    auto range = [&](const Object& o, std::array<int, 3>& a, std::array<int, 3>& b) {
        const Vec3 olo = (o.bound.c - Vec3(o.bound.r + pad) - lo_) / cellSize_;
        const Vec3 ohi = (o.bound.c + Vec3(o.bound.r + pad) - lo_) / cellSize_;
        for (int k = 0; k < 3; ++k) {
            a[k] = clampedCell(olo[k], res_[k]);
            b[k] = clampedCell(ohi[k], res_[k]);
        }
    };
    const std::int64_t referenceCap =
        std::min(kMaxReferences, std::max(kMinReferenceCap, kReferencesPerObject * std::int64_t(scene.size())));
    for (;;) {
        cellSize_ = size / Vec3(res_[0], res_[1], res_[2]);
        std::int64_t references = 0;
        for (int id = 0; id < scene.size() && references <= referenceCap; ++id) {
            std::array<int, 3> a, b;
            range(scene.objects[id], a, b);
            references += std::int64_t(b[0] - a[0] + 1) * (b[1] - a[1] + 1) * (b[2] - a[2] + 1);
        }
        if (references <= referenceCap || res_ == std::array<int, 3>{1, 1, 1}) break;
        for (int& r : res_) r = std::max(1, r / 2);
    }
    // [grid-caps]

    // Count, then fill (compressed rows)
    const std::size_t cells = std::size_t(res_[0]) * res_[1] * res_[2];
    std::vector<std::size_t> count(cells + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        for (int id = 0; id < scene.size(); ++id) {
            std::array<int, 3> a, b;
            range(scene.objects[id], a, b);
            for (int z = a[2]; z <= b[2]; ++z)
                for (int y = a[1]; y <= b[1]; ++y)
                    for (int x = a[0]; x <= b[0]; ++x) {
                        const std::size_t c = cellIndex(x, y, z);
                        if (pass == 0) ++count[c + 1];
                        else ids_[cellStart_[c] + count[c]++] = id;
                    }
        }
        if (pass == 0) {
            for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
            cellStart_ = count;
            ids_.resize(cellStart_[cells]);
            std::fill(count.begin(), count.end(), 0);
        }
    }
}

std::vector<int> UniformGrid::objectsInBox(const Vec3& lo, const Vec3& hi) const {
    std::vector<int> out;
    if (ids_.empty()) return out;
    std::array<int, 3> a, b;
    for (int k = 0; k < 3; ++k) {
        a[k] = clampedCell((lo[k] - lo_[k]) / cellSize_[k], res_[k]);
        b[k] = clampedCell((hi[k] - lo_[k]) / cellSize_[k], res_[k]);
    }
    for (int z = a[2]; z <= b[2]; ++z)
        for (int y = a[1]; y <= b[1]; ++y)
            for (int x = a[0]; x <= b[0]; ++x) {
                const std::size_t c = cellIndex(x, y, z);
                out.insert(out.end(), ids_.begin() + cellStart_[c], ids_.begin() + cellStart_[c + 1]);
            }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template <class Visit>
void UniformGrid::walk(const Ray& r, double tmax, int margin, Visit visit) const {
    // The grid widened by `margin` cells on every side (cells indexed from -margin)
    const Vec3 lo = lo_ - double(margin) * cellSize_;
    const Vec3 hi = hi_ + double(margin) * cellSize_;
    const std::array<int, 3> res{res_[0] + 2 * margin, res_[1] + 2 * margin, res_[2] + 2 * margin};
    // [grid-walk]
    // Clip the ray to the grid's box (slab test)
    double t0 = 0.0, t1 = tmax;
    for (int k = 0; k < 3; ++k) {
        if (r.d[k] == 0.0) {
            if (r.o[k] < lo[k] || r.o[k] > hi[k]) return;
            continue;
        }
        double a = (lo[k] - r.o[k]) / r.d[k], b = (hi[k] - r.o[k]) / r.d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (!(t0 <= t1)) return;
    // The first cell, and how far to each next cell boundary (Amanatides and Woo)
    const Vec3 p = r.at(t0);
    int cell[3], step[3], stop[3];
    double next[3], delta[3];
    for (int k = 0; k < 3; ++k) {
        cell[k] = clampedCell((p[k] - lo[k]) / cellSize_[k], res[k]);
        if (r.d[k] > 0.0) {
            step[k] = 1;
            stop[k] = res[k];
            next[k] = (lo[k] + (cell[k] + 1) * cellSize_[k] - r.o[k]) / r.d[k];
            delta[k] = cellSize_[k] / r.d[k];
        } else if (r.d[k] < 0.0) {
            step[k] = -1;
            stop[k] = -1;
            next[k] = (lo[k] + cell[k] * cellSize_[k] - r.o[k]) / r.d[k];
            delta[k] = -cellSize_[k] / r.d[k];
        } else {
            step[k] = 0;
            stop[k] = -2;
            next[k] = kNoHit;
            delta[k] = kNoHit;
        }
    }
    for (;;) {
        // Visit the cell; it says whether to go on, knowing where the ray leaves it
        const int k = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        const double exit = next[k];
        const int at[3] = {cell[0] - margin, cell[1] - margin, cell[2] - margin};
        if (!visit(at, exit) || exit > t1) break;
        cell[k] += step[k];
        if (cell[k] == stop[k]) break;
        next[k] += delta[k];
    }
    // [grid-walk]
}

void UniformGrid::newStamp() const {
    if (++stamp_ == 0) {  // wrapped: forget every mark
        std::fill(mailbox_.begin(), mailbox_.end(), 0);
        stamp_ = 1;
    }
}

Answer UniformGrid::nearest(const Query& q, Counters& n) const {
    Answer best;
    if (ids_.empty()) return best;
    newStamp();
    walk(q.ray, q.tmax, 0, [&](const int* cell, double exit) {
        // Test the cell's objects, each once per ray
        const std::size_t c = cellIndex(cell[0], cell[1], cell[2]);
        for (std::size_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i) {
            const int id = ids_[i];
            if (mailbox_[id] == stamp_) continue;
            mailbox_[id] = stamp_;
            testObject(scene_, q, id, best, n);
        }
        // A hit before this cell's exit is final (a hair of margin keeps ties exact)
        return !(best.t < exit * (1.0 - 1e-12) - 1e-300);
    });
    return best;
}

void UniformGrid::cull(SphereCull& c) const {
    objectsNearSegment(c.a, c.b, c.radius, candidates_);
    for (int id : candidates_) {
        const double d = c.distance(scene_.objects[id].bound);
        if (d <= c.limit) c.found(id, d);
    }
}

void UniformGrid::objectsNearSegment(const Vec3& a, const Vec3& b, double radius, std::vector<int>& out) const {
    out.clear();
    if (ids_.empty()) return;
    // Cells within `ring` cells of those the segment crosses hold everything within `radius`
    const double side = nearRadius();
    const double rings = std::ceil(radius / side);
    if (!(rings <= 3.0)) {  // a wide neighbourhood (or an absurd radius): the box is cheaper
        out = objectsInBox(glm::min(a, b) - Vec3(radius), glm::max(a, b) + Vec3(radius));
        return;
    }
    const int ring = int(rings);
    newStamp();
    const double length = glm::length(b - a);
    const Ray r{a, length > 0.0 ? (b - a) / length : Vec3(1.0, 0.0, 0.0)};
    // Walk the grid widened by the ring, so parts of the segment just outside it count too
    walk(r, length, ring, [&](const int* cell, double) {
        for (int z = std::max(0, cell[2] - ring); z <= std::min(res_[2] - 1, cell[2] + ring); ++z)
            for (int y = std::max(0, cell[1] - ring); y <= std::min(res_[1] - 1, cell[1] + ring); ++y)
                for (int x = std::max(0, cell[0] - ring); x <= std::min(res_[0] - 1, cell[0] + ring); ++x) {
                    const std::size_t c = cellIndex(x, y, z);
                    for (std::size_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i) {
                        const int id = ids_[i];
                        if (mailbox_[id] == stamp_) continue;
                        mailbox_[id] = stamp_;
                        out.push_back(id);
                    }
                }
        return true;
    });
}

}  // namespace rc
