// No allocation per ray: a render allocates when it meets something new (a ray-tree path,
// a blocker list, a band of breadth-first rays), never for the rays themselves.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

#include "render/render_session.h"
#include "scene/builtin_scenes.h"

// Count every operator new of this test binary. Sanitizer builds keep their own allocator.
#if !defined(__SANITIZE_ADDRESS__)
namespace {
std::atomic<long> allocations{0};
}
void* operator new(std::size_t n) {
    ++allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace rc;

namespace {
struct Measured {
    long allocations;
    std::uint64_t rays;
    std::uint64_t directionLists;  ///< built (in the lists' arena, no allocation each)
};
Measured render(const std::shared_ptr<const Scene>& scene, AccelKind accel, CacheKind cache, OrderKind order,
                int size, int height = 0) {
    RenderOptions o;
    o.width = size;
    o.height = height > 0 ? height : size;
    o.accel = accel;
    o.cache = cache;
    o.order = order;
    RenderSession s(scene, o);
    const long before = allocations.load();
    s.run();
    return {allocations.load() - before, s.counters().totalRays(), s.counters().directionListsBuilt};
}
}  // namespace

TEST_CASE("the ray loop does not allocate", "[alloc]") {
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:5"));
    for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
        for (CacheKind cache : allCacheKinds()) {
            for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
                INFO(toString(accel) << " " << toString(cache) << " " << toString(order));
                const Measured small = render(scene, accel, cache, order, 48);
                const Measured large = render(scene, accel, cache, order, 96);
                REQUIRE(large.rays > 3 * small.rays);
                REQUIRE(large.allocations > 0);  // the counter counts: paths and children are new
                // Allocations follow what is new (lists, bands), a small fraction of the rays;
                // direction lists are kept in large blocks (search/list_arena.h), not each its own
                REQUIRE(large.allocations * 5 < long(large.rays));
                if (large.directionLists > 100) REQUIRE(large.allocations < long(large.directionLists));
                // Scanline order without blocker lists: four times the rays, no more allocations
                if (order == OrderKind::Scanline && (cache == CacheKind::None || cache == CacheKind::Cylinder))
                    REQUIRE(large.allocations == small.allocations);
            }
        }
    }
}
TEST_CASE("breadth-first bands reuse the memory of the bands before", "[alloc]") {
    // Four times the bands of the same width: the rays of each path in a band go into the
    // buffer the path had in the band before, so only a path's first bands allocate
    auto scene = std::make_shared<const Scene>(makeBuiltin("cube:5"));
    for (CacheKind cache : {CacheKind::None, CacheKind::Cylinder}) {
        INFO(toString(cache));
        const Measured few = render(scene, AccelKind::Linear, cache, OrderKind::BreadthFirst, 64, 64);
        const Measured many = render(scene, AccelKind::Linear, cache, OrderKind::BreadthFirst, 64, 256);
        REQUIRE(many.rays > 3 * few.rays);
        REQUIRE(many.allocations - few.allocations < few.allocations / 4);
    }
}
#else
// AddressSanitizer replaces operator new with its own: counting is not possible there, and
// the build says so instead of passing in silence
TEST_CASE("the allocation tests are skipped under AddressSanitizer", "[alloc]") {
    WARN("SKIPPED: built with AddressSanitizer, whose allocator these tests cannot count; "
         "the default build runs them");
}
#endif
