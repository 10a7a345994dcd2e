#pragma once
/// \file
/// \brief RayCache's addition (blocker+): the objects a ray can meet, listed per site and
/// cell of directions, so that a miss tests a few candidates instead of the whole scene.
///
/// Hanrahan's cache misses whenever a ray does not hit the object its path last hit, and
/// rays that hit nothing have no list at all (the paper: "the cache hit test is not very
/// successful when a ray had not previously hit an object. Improving this case would
/// significantly speed up the program"). Both then search the whole scene.
///
/// The directions around a site are cut into cells, a cube map's squares, each within a
/// cone of directions. A ray leaving from anywhere in the site's sphere in a direction of
/// the cone can meet only the objects whose bounding spheres the cone of rays meets
/// (CellCull): the cell's list. A miss then tests that list, nearest first, and is
/// answered exactly; the list is built the first time its (site, cell) is met, like a
/// blocker list, and kept. This is in the spirit of Arvo and Kirk's ray classification
/// (1987), a year after the paper, grown lazily from the rays that ask.
#include <cstdint>
#include <span>
#include <vector>

#include "search/blocker_lists.h"
#include "search/list_arena.h"
#include "search/reach_order.h"

namespace rc {

/// One cell's list: the objects rays leaving its site in its cell can meet, nearest first,
/// each with its reach (as in a BlockerList), kept in the lists' arena.
struct DirectionList {
    int origin = -1;  ///< its site
    int target = -1;  ///< its cell
    bool bypass = false;  ///< never: even a long list is worth testing (as BlockerList's)
    std::span<const int> ids;
    std::span<const double> reach;
    ListArena::Mark start;  ///< where the arena stood before it
};

/// Lists of the objects rays leaving a site in a cell of directions can meet.
class DirectionLists {
public:
    /// Cells per side of each of the cube's six faces, around an object (or tile)
    static constexpr int kCellsPerSide = 2;
    /// And around the eye
    static constexpr int kEyeCellsPerSide = 32;
    /// Sites are those of `sites` (objects, the eye, tiles); candidates come from `search`.
    /// `siteOrders`: each site sorts every object once and its cells pick theirs from that
    /// order, where the scene is small enough (kMostOrderEntries); else (or false) each
    /// cell culls through `search` and sorts its own. The lists are the same.
    DirectionLists(const Scene& scene, const CompleteSearch& search, const BlockerLists& sites, bool siteOrders = true);

    /// The cell of unit direction `d`, with `side` cells per side of a face.
    static int cell(const Vec3& d, int side);
    /// The list of rays leaving `site` in the cell of `d`, built on first use and counted
    /// in `n`. Even a long list is worth testing: nearest first, it is left at the first hit.
    /// Tries first the list numbered `memo`, and leaves the list's number there.
    const DirectionList& get(int site, const Vec3& d, std::uint32_t& memo, Counters& n);
    /// Lists built so far (in the order built).
    std::size_t size() const { return lists_.size(); }

    /// The quick test of a cell's cone (axis a, half-angle alpha) against `count` objects'
    /// aims (unit direction x, y, z from the site, cosine and sine of the half-angle beta
    /// each subtends), in single precision: bit k of `maybe` is set when object k may meet
    /// the cone (within a margin of its edge), bit k of `sure` when it clearly does. Each
    /// array holds (count + 63) / 64 words. `simd`: eight at a time with AVX2 where the
    /// processor has it, the same operations in the same order (the same bits as without).
    struct QuickCone {
        float ax, ay, az, cosA, sinA;
    };
    static void quickTest(const QuickCone& c, const float* x, const float* y, const float* z, const float* cosB,
                          const float* sinB, std::size_t count, std::uint64_t* maybe, std::uint64_t* sure,
                          bool simd = true);
    /// Forgets every list but the first `n` built (the sites' orders, which depend on the
    /// scene alone, are kept).
    void truncate(std::size_t n);

private:
    /// The cone holding a cell's directions: its axis and the cosine of its half-angle
    struct CellCone {
        Vec3 axis{0.0};
        double cosHalf = 1.0;
    };
    static CellCone cellCone(int cell, int side);
    /// Cells per side of a face around `site`.
    int side(int site) const;
    void build(DirectionList& list, int site, int cell, Counters& n);
    /// Every object seen from `site`, nearest first (by reach, then id): sorted the first
    /// time one of the site's cells is built, and shared by all of them.
    std::size_t nearestFirst(int site);
    /// The reach from `from` of object `id`'s bounding sphere: as sortNearestFirst() computes it
    double reachFrom(const Sphere& from, int id) const;
    /// Scenes whose sites' orders would hold more entries (objects x sites) than this, 4
    /// bytes and 20 bytes each, find each cell's objects through the complete search's cull and sort them
    static constexpr std::size_t kMostOrderEntries = std::size_t(1) << 21;
    const Scene& scene_;
    const CompleteSearch& search_;
    const BlockerLists& sites_;
    double slack_;
    std::vector<DirectionList> lists_;
    /// Each site's cells, read directly: per site, where its cells' list numbers start in
    /// cellLists_ (kNoCells until one of its cells is met); there, each cell's list number
    /// or kNoList. No hashing: a site has only 6 side^2 cells
    std::vector<std::uint32_t> cellsAt_;
    std::vector<std::uint32_t> cellLists_;
    static constexpr std::uint32_t kNoCells = std::uint32_t(-1), kNoList = std::uint32_t(-1);
    /// The lists' objects and reaches, in large blocks (no two allocations per list)
    ListArena arena_;
    /// The sites' orders and aims below, in blocks of their own: a truncate keeps them
    ListArena orderArena_;
    std::vector<std::pair<double, int>> found_;  ///< scratch of the list being built
    /// Per site: where its order starts in orders_, or kNoOrder (empty: none kept, see kMostOrderEntries)
    std::vector<std::uint32_t> orderAt_;
    /// The sites' orders, one after another: object ids only (a reach is recomputed, the
    /// same double, for the objects a cell keeps); room for every site's, taken at the first
    /// (pages are touched as they are used)
    std::uint32_t* orders_ = nullptr;
    std::size_t ordered_ = 0;  ///< entries of orders_ (and of each aim array) written
    ReachOrder sorting_;  ///< scratch: a site's (reach, id) pairs as they are sorted
    /// Beside each entry of orders_: the object's direction from the site (x, y, z) and the
    /// cosine and sine of the half-angle its grown sphere subtends, in single precision and
    /// in arrays of their own, so one loop tests many at once: a quick test that only ever
    /// keeps too many objects, the exact one deciding (build())
    float *aimX_ = nullptr, *aimY_ = nullptr, *aimZ_ = nullptr, *aimCos_ = nullptr, *aimSin_ = nullptr;
    std::vector<std::uint64_t> maybe_, sure_;  ///< scratch: the quick test's verdicts on a site's order
    std::vector<Sphere> bounds_;  ///< every object's bounding sphere, by id, in one array
    static constexpr std::uint32_t kNoOrder = std::uint32_t(-1);
};

}  // namespace rc
