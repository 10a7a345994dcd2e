#include "search/direction_lists.h"

#include <algorithm>
#include <cmath>
#include <bit>
#include <stdexcept>

#include <glm/geometric.hpp>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RC_CELL_AVX2 1
#include <immintrin.h>
#endif

namespace rc {

namespace {
/// The direction of point (x, y) of face `face` of the cube [-1, 1]^3: axis face / 2,
/// negative for odd faces, x and y along the next two axes.
[[maybe_unused]] Vec3 faceDirection(int face, double x, double y) {
    // BEGIN SOLUTION 07
    const int axis = face / 2;
    Vec3 d{0.0};
    d[axis] = face % 2 ? -1.0 : 1.0;
    d[(axis + 1) % 3] = x;
    d[(axis + 2) % 3] = y;
    return glm::normalize(d);
    // END SOLUTION
    // BEGIN STUB
    // (void)face, (void)x, (void)y;
    // throw std::logic_error("faceDirection: the cells of directions are tutorial 07's challenge: this edition has none (blocker+dir is blocker+)");
    // END STUB
}

/// How far sphere s lies from the cone of rays from `apex` around `axis` (half-angle whose
/// cosine and sine are cosA and sinA), less `reach` (negative: they meet).
inline double coneDistance(const Vec3& apex, double reach, const Vec3& axis, double cosA, double sinA,
                           const Sphere& s) {
    // BEGIN SOLUTION 07
    // [cone-distance]
    // The distance from the sphere to the cone (negative inside), measured in the half-plane
    // through the axis: x along it, y away from it. Beside the cone's side it is the
    // distance to the side; behind the apex, to the apex. A distance is 1-Lipschitz: a lower
    // bound for any sphere inside s
    const Vec3 v = s.c - apex;
    const double x = glm::dot(v, axis), y = glm::length(glm::cross(v, axis));
    const double side = x * cosA + y * sinA < 0.0 ? glm::length(v) : y * cosA - x * sinA;
    return side - s.r - reach;
    // [cone-distance]
    // END SOLUTION
    // BEGIN STUB
    // (void)apex, (void)reach, (void)axis, (void)cosA, (void)sinA, (void)s;
    // throw std::logic_error("coneDistance: the cells of directions are tutorial 07's challenge: this edition has none (blocker+dir is blocker+)");
    // END STUB
}

/// The objects whose bounding spheres rays leaving a ball in a cone of directions can meet:
/// those whose spheres, grown by the ball's radius, meet the cone of rays from its centre
/// (a ray from a point of the ball runs parallel to one from the centre, never farther
/// than the radius from it).
struct CellCull final : SphereCull {
    CellCull(const Vec3& apex, double reach, const Vec3& axis, double cosHalf, std::vector<std::pair<double, int>>& out)
        : apex(apex), reach(reach), axis(axis), cosA(cosHalf), sinA(std::sqrt(1.0 - cosHalf * cosHalf)),
          out(out) {
        limit = 0.0;
    }
    double distance(const Sphere& s) override { return coneDistance(apex, reach, axis, cosA, sinA, s); }
    void found(int id, double) override {
        out.emplace_back(0.0, id);  // its reach is set once the list is known
    }
    Vec3 apex;
    double reach;
    Vec3 axis;
    double cosA, sinA;
    std::vector<std::pair<double, int>>& out;
};
}  // namespace

namespace {
/// The quick test of one object: 0 clearly outside, 1 too near the edge to tell, 2 clearly inside
inline int quickVerdict(const DirectionLists::QuickCone& c, float x, float y, float z, float cosB, float sinB) {
    const float aim = x * c.ax + y * c.ay + z * c.az, edge = c.cosA * cosB - c.sinA * sinB;
    return (aim >= edge - 1e-4f) + (aim >= edge + 1e-4f);
}

#ifdef RC_CELL_AVX2
/// Eight objects at a time, each as quickVerdict() computes it (no fused multiply-add: this
/// function's target has none), from `begin` (a multiple of 64) to the last whole eight
__attribute__((target("avx2"))) std::size_t quickEights(const DirectionLists::QuickCone& c, const float* x,
                                                        const float* y, const float* z, const float* cosB,
                                                        const float* sinB, std::size_t count, std::uint64_t* maybe,
                                                        std::uint64_t* sure) {
    const __m256 ax = _mm256_set1_ps(c.ax), ay = _mm256_set1_ps(c.ay), az = _mm256_set1_ps(c.az);
    const __m256 cosA = _mm256_set1_ps(c.cosA), sinA = _mm256_set1_ps(c.sinA), margin = _mm256_set1_ps(1e-4f);
    std::size_t k = 0;
    for (; k + 8 <= count; k += 8) {
        const __m256 aim = _mm256_add_ps(
            _mm256_add_ps(_mm256_mul_ps(_mm256_loadu_ps(x + k), ax), _mm256_mul_ps(_mm256_loadu_ps(y + k), ay)),
            _mm256_mul_ps(_mm256_loadu_ps(z + k), az));
        const __m256 edge = _mm256_sub_ps(_mm256_mul_ps(cosA, _mm256_loadu_ps(cosB + k)),
                                          _mm256_mul_ps(sinA, _mm256_loadu_ps(sinB + k)));
        const auto low = std::uint64_t(_mm256_movemask_ps(_mm256_cmp_ps(aim, _mm256_sub_ps(edge, margin), _CMP_GE_OQ)));
        const auto high = std::uint64_t(_mm256_movemask_ps(_mm256_cmp_ps(aim, _mm256_add_ps(edge, margin), _CMP_GE_OQ)));
        maybe[k / 64] |= low << (k % 64);
        sure[k / 64] |= high << (k % 64);
    }
    return k;
}
#endif
}  // namespace

void DirectionLists::quickTest(const QuickCone& c, const float* x, const float* y, const float* z,
                               const float* cosB, const float* sinB, std::size_t count, std::uint64_t* maybe,
                               std::uint64_t* sure, bool simd) {
    std::fill(maybe, maybe + (count + 63) / 64, 0);
    std::fill(sure, sure + (count + 63) / 64, 0);
    std::size_t k = 0;
#ifdef RC_CELL_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (simd && avx2) k = quickEights(c, x, y, z, cosB, sinB, count, maybe, sure);
#else
    (void)simd;
#endif
    for (; k < count; ++k) {
        const int v = quickVerdict(c, x[k], y[k], z[k], cosB[k], sinB[k]);
        maybe[k / 64] |= std::uint64_t(v >= 1) << (k % 64);
        sure[k / 64] |= std::uint64_t(v == 2) << (k % 64);
    }
}

DirectionLists::DirectionLists(const Scene& scene, const CompleteSearch& search, const BlockerLists& sites,
                               bool siteOrders)
    : scene_(scene), search_(search), sites_(sites) {
    slack_ = 1e-9 * scene.extent();
    cellsAt_.assign(std::size_t(sites.sites()), kNoCells);
    if (siteOrders && std::size_t(scene.size()) * std::size_t(sites.sites()) <= kMostOrderEntries) {
        orderAt_.assign(std::size_t(sites.sites()), kNoOrder);
        bounds_.reserve(scene.objects.size());
        for (const Object& o : scene.objects) bounds_.push_back(o.bound);
    }
}

double DirectionLists::reachFrom(const Sphere& from, int id) const {
    const Sphere& s = bounds_[std::size_t(id)];
    return glm::length(s.c - from.c) - s.r - from.r - slack_;
}

std::size_t DirectionLists::nearestFirst(int site) {
    std::uint32_t& at = orderAt_[std::size_t(site)];
    if (at == kNoOrder) {
        // [site-order]
        // Every object by its reach from the site, as sortNearestFirst() orders a list: a
        // cell's list is then the objects of this order its cone of rays meets, in order
        if (!orders_) {
            // Room for every site at once (no copy as it grows: pages are touched as used)
            const std::size_t all = orderAt_.size() * bounds_.size();
            orders_ = orderArena_.take<std::uint32_t>(all);
            for (float** aim : {&aimX_, &aimY_, &aimZ_, &aimCos_, &aimSin_}) *aim = orderArena_.take<float>(all);
        }
        at = std::uint32_t(ordered_);
        const Sphere from = sites_.siteSphere(site);
        sorting_.clear();
        for (int id = 0; id < int(bounds_.size()); ++id) sorting_.push(reachFrom(from, id), std::uint32_t(id));
        sorting_.sort();
        // Only the ids are kept: a cell's build recomputes the reach of the few it keeps
        for (const ReachOrder::Entry& e : sorting_.entries()) orders_[ordered_++] = e.id;
        const std::uint32_t* first = orders_ + at;
        // [site-order]
        // Each object's aim: a sphere of radius g at distance L subtends a half-angle
        // beta = asin(g / L); one the site's sphere reaches is seen in every direction
        const double reach = from.r + slack_;
        std::size_t k = at;
        for (auto it = first; it != orders_ + ordered_; ++it, ++k) {
            const Sphere& s = bounds_[*it];
            const Vec3 v = s.c - from.c;
            const double length = glm::length(v), g = s.r + reach;
            // Else all zero: the quick test cannot tell (0 is within its margin of 0), the exact one decides
            const bool seen = length > g * (1.0 + 1e-6);
            const double sinB = seen ? g / length : 0.0;
            aimX_[k] = seen ? float(v.x / length) : 0.0f;
            aimY_[k] = seen ? float(v.y / length) : 0.0f;
            aimZ_[k] = seen ? float(v.z / length) : 0.0f;
            aimCos_[k] = seen ? float(std::sqrt(1.0 - sinB * sinB)) : 0.0f;
            aimSin_[k] = float(sinB);
        }
    }
    return at;
}

DirectionLists::CellCone DirectionLists::cellCone(int cell, int side) {
    // BEGIN SOLUTION 07
    // Around the direction of the square's centre, out to its farthest corner (a cap holds
    // a convex spherical square when it holds its corners)
    const int face = cell / (side * side), i = cell / side % side, j = cell % side;
    auto at = [&](double u, double v) { return faceDirection(face, -1.0 + 2.0 * u / side, -1.0 + 2.0 * v / side); };
    CellCone c;
    c.axis = at(i + 0.5, j + 0.5);
    for (int corner = 0; corner < 4; ++corner)
        c.cosHalf = std::min(c.cosHalf, glm::dot(c.axis, at(i + corner % 2, j + corner / 2)));
    c.cosHalf -= 1e-9;  // rounding only ever widens a cone
    return c;
    // END SOLUTION
    // BEGIN STUB
    // (void)cell, (void)side;
    // throw std::logic_error("DirectionLists::cellCone: the cells of directions are tutorial 07's challenge: this edition has none (blocker+dir is blocker+)");
    // END STUB
}

int DirectionLists::side(int site) const {
    // [cells-per-side]
    // Seen from an object, its neighbours are near and wide: a few cells per face are
    // enough, and each list serves many rays. Seen from the eye, the whole scene fits in a
    // cone a few cells wide: the eye's cells are much finer
    return site == sites_.eyeSite() ? kEyeCellsPerSide : kCellsPerSide;
    // [cells-per-side]
}

int DirectionLists::cell(const Vec3& d, int side) {
    // BEGIN SOLUTION 07
    // [direction-cell]
    // The cube face the direction leaves through, and the square of that face
    const Vec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    auto square = [&](double x) { return std::min(int((x / a[axis] + 1.0) * 0.5 * side), side - 1); };
    return (face * side + square(d[(axis + 1) % 3])) * side + square(d[(axis + 2) % 3]);
    // [direction-cell]
    // END SOLUTION
    // BEGIN STUB
    // (void)d, (void)side;
    // throw std::logic_error("DirectionLists::cell: the cells of directions are tutorial 07's challenge: this edition has none (blocker+dir is blocker+)");
    // END STUB
}

const DirectionList& DirectionLists::get(int site, const Vec3& d, std::uint32_t& memo, Counters& n) {
    const int c = cell(d, side(site));
    // A path's misses mostly leave the same site in the same cell as its last one
    if (memo < lists_.size() && lists_[memo].origin == site && lists_[memo].target == c) return lists_[memo];
    // Else the site's own cells, read directly
    std::uint32_t& first = cellsAt_[std::size_t(site)];
    if (first == kNoCells) {
        const int s = side(site);
        first = std::uint32_t(cellLists_.size());
        cellLists_.resize(cellLists_.size() + std::size_t(6 * s * s), kNoList);
    }
    std::uint32_t& number = cellLists_[first + std::uint32_t(c)];
    if (number != kNoList) {
        memo = number;
        return lists_[number];
    }
    number = std::uint32_t(lists_.size());
    memo = number;
    DirectionList& list = lists_.emplace_back();
    list.start = arena_.mark();
    build(list, site, c, n);
    return list;
}

void DirectionLists::build(DirectionList& list, int site, int cell, Counters& n) {
    list.origin = site;
    list.target = cell;
    // [build-direction-list]
    // Every object whose bounding sphere a ray from the site's sphere in the cell can meet
    const Sphere from = sites_.siteSphere(site);
    const CellCone cone = cellCone(cell, side(site));
    ++n.directionListsBuilt;
    if (!orderAt_.empty()) {
        // Those of the site's order, nearest first: a ray that has hit something at t
        // cannot hit first what lies farther
        const std::size_t at = nearestFirst(site);
        const std::uint32_t* order = orders_ + at;
        const double reach = from.r + slack_, sinA = std::sqrt(1.0 - cone.cosHalf * cone.cosHalf);
        // [cell-quick-test]
        // The sphere meets the cone when its direction is within alpha + beta of the axis:
        // cos(angle) >= cos(alpha + beta) = cos(alpha) cos(beta) - sin(alpha) sin(beta). In single
        // precision, with a margin a thousand times its rounding, the quick test keeps every
        // object the exact distance keeps and drops every other one, but for those near
        // the cone's edge, which the exact distance decides
        const QuickCone quick{float(cone.axis.x), float(cone.axis.y), float(cone.axis.z), float(cone.cosHalf),
                              float(sinA)};
        const std::size_t count = bounds_.size(), words = (count + 63) / 64;
        maybe_.resize(words);
        sure_.resize(words);
        // Eight at a time where the processor can: bits of "may meet" and "clearly meets"
        quickTest(quick, aimX_ + at, aimY_ + at, aimZ_ + at, aimCos_ + at, aimSin_ + at, count, maybe_.data(),
                  sure_.data());
        found_.clear();
        // Most objects are clearly outside: only the set bits are visited, in order
        for (std::size_t w = 0; w < words; ++w)
            for (std::uint64_t bits = maybe_[w]; bits != 0; bits &= bits - 1) {
                const std::size_t k = 64 * w + std::size_t(std::countr_zero(bits));
                if ((sure_[w] >> (k % 64) & 1) != 0 ||
                    coneDistance(from.c, reach, cone.axis, cone.cosHalf, sinA, bounds_[order[k]]) <= 0.0)
                    found_.emplace_back(reachFrom(from, int(order[k])), int(order[k]));
            }
        // [cell-quick-test]
    } else {
        // A large scene: the cull finds them, then they are sorted
        found_.clear();
        CellCull cull(from.c, from.r + slack_, cone.axis, cone.cosHalf, found_);
        search_.cull(cull);
        sortNearestFirst(scene_, from, slack_, found_);
    }
    // [build-direction-list]
    // Kept in the arena, one after another
    int* ids = arena_.take<int>(found_.size());
    double* reach = arena_.take<double>(found_.size());
    for (std::size_t k = 0; k < found_.size(); ++k) {
        reach[k] = found_[k].first;
        ids[k] = found_[k].second;
    }
    list.ids = {ids, found_.size()};
    list.reach = {reach, found_.size()};
    n.directionListEntries += list.ids.size();
}

void DirectionLists::truncate(std::size_t n) {
    if (n > lists_.size()) throw std::logic_error("DirectionLists::truncate: cannot grow");
    if (n < lists_.size()) arena_.rewind(lists_[n].start);
    lists_.resize(n);
    for (std::uint32_t& number : cellLists_)
        if (number != kNoList && number >= n) number = kNoList;
}

}  // namespace rc
