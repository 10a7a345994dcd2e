#pragma once
/// \file
/// \brief A uniform grid walked with a 3D-DDA (Fujimoto and Iwata 1985; Amanatides and Woo
/// 1987): a complete search that visits only the cells a ray passes through.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "search/complete_search.h"

namespace rc {

/// Cells of equal size over the scene's bounding box, each listing the objects whose
/// (slightly widened) bounding boxes overlap it. Returns exactly what LinearSearch returns,
/// ties included: a cell's hits are only final once they lie before the cell's exit.
class UniformGrid final : public CompleteSearch {
public:
    /// At most this many cells (128 per axis), and at most max(kMinReferenceCap,
    /// kReferencesPerObject * n) object references, never more than kMaxReferences: where the
    /// objects overlap so much that a fine grid would list them many times over (coincident
    /// spheres), the grid gets coarser, down to one cell, which is the linear scan.
    static constexpr std::int64_t kMaxCells = std::int64_t(1) << 21;
    static constexpr std::int64_t kReferencesPerObject = 64;
    static constexpr std::int64_t kMinReferenceCap = std::int64_t(1) << 22;
    static constexpr std::int64_t kMaxReferences = std::int64_t(1) << 27;

    /// `density`: cells per object, about; the grid has about density * n cells.
    explicit UniformGrid(const Scene& scene, double density = 4.0);
    Answer nearest(const Query& q, Counters& n) const override;
    std::string name() const override { return "grid"; }
    std::array<int, 3> resolution() const { return res_; }
    /// Object references held by all cells together (an object counts once per cell).
    std::int64_t references() const { return std::int64_t(ids_.size()); }
    /// Objects whose bounding boxes overlap the box [lo, hi] (each once, ascending).
    std::vector<int> objectsInBox(const Vec3& lo, const Vec3& hi) const;
    /// Objects whose bounding boxes come within `radius` of the segment a-b, and maybe a
    /// few more: the cells within ceil(radius / smallest side) cells of those it crosses.
    void objectsNearSegment(const Vec3& a, const Vec3& b, double radius, std::vector<int>& out) const;
    /// Measures the objects near the cull's hint segment only.
    void cull(SphereCull& c) const override;
    /// The smallest side of a cell.
    double nearRadius() const override { return std::min(cellSize_.x, std::min(cellSize_.y, cellSize_.z)); }

private:
    std::size_t cellIndex(int x, int y, int z) const {
        return (std::size_t(z) * std::size_t(res_[1]) + std::size_t(y)) * std::size_t(res_[0]) + std::size_t(x);
    }
    /// 3D-DDA along `r` up to `tmax` over the grid widened by `margin` cells; `visit(cell,
    /// exit)` gets each cell (indices may be outside [0, res) by up to `margin`) and the
    /// distance where the ray leaves it, and returns whether to go on.
    template <class Visit>
    void walk(const Ray& r, double tmax, int margin, Visit visit) const;
    void newStamp() const;
    Vec3 lo_{0.0}, hi_{0.0}, cellSize_{1.0};
    std::array<int, 3> res_{1, 1, 1};
    std::vector<std::size_t> cellStart_;  ///< CSR: objects of cell c are ids_[start[c], start[c+1])
    std::vector<int> ids_;
    mutable std::vector<std::uint32_t> mailbox_;  ///< last query that tested each object
    mutable std::uint32_t stamp_ = 0;
    mutable std::vector<int> candidates_;  ///< scratch of cull()
};

}  // namespace rc
