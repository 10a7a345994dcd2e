// Exactness: every cache strategy answers every ray exactly as the complete search does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include <glm/geometric.hpp>

#include "random_scenes.h"
#include "render/render_session.h"
#include "geometry/cone.h"
#include "scene/builtin_scenes.h"
#include "search/accelerator.h"
#include "search/blocker_cache.h"
#include "search/bounding_volume_hierarchy.h"
#include "search/cylinder_cache.h"
#include "search/direction_lists.h"
#include "search/linear_search.h"
#include "search/packed_spheres.h"
#include "search/reach_order.h"
#include "search/sphere_batch.h"
#include "uniform.h"

using namespace rc;
using rc::testing::Layout;

namespace {
const Layout kLayouts[] = {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Transparent,
                           Layout::Polygons};

// Coherent query streams: eye rays sweeping, rays leaving surfaces both ways, shadow rays
std::vector<Query> queryStream(const Scene& s, std::uint64_t seed) {
    Random rng(seed);
    const Uniform u{-1.0, 1.0};
    std::vector<Query> out;
    const Vec3 eye = s.camera.from;
    for (int i = 0; i < 400; ++i) {
        // a slowly turning eye ray
        const Vec3 d = glm::normalize(s.camera.at - eye + Vec3(0.004 * (i % 40) - 0.08, 0.004 * (i / 40) - 0.02, 0));
        out.push_back({{eye, d}, kNoHit, {}, RayKind::Primary, -1});
    }
    for (int obj = 0; obj < s.size(); ++obj) {
        if (s.objects[obj].shape != Shape::Sphere) continue;
        const Sphere& sp = s.spheres[s.objects[obj].index];
        Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
        for (int k = 0; k < 30; ++k) {
            n = glm::normalize(n + 0.05 * Vec3(u(rng), u(rng), u(rng)));
            const Vec3 p = sp.c + n * sp.r;
            Vec3 d = glm::normalize(n + 0.8 * Vec3(u(rng), u(rng), u(rng)));
            out.push_back({{p, d}, kNoHit, {obj, glm::dot(d, n) < 0.0}, RayKind::Reflection, -1});
            out.push_back({{p, -d}, kNoHit, {obj, glm::dot(-d, n) < 0.0}, RayKind::Refraction, -1});
            for (int l = 0; l < int(s.lights.size()); ++l) {
                const Vec3 toLight = s.lights[l].position - p;
                const Vec3 ld = glm::normalize(toLight);
                out.push_back({{p, ld}, glm::length(toLight), {obj, glm::dot(ld, n) < 0.0}, RayKind::Shadow, l});
            }
        }
    }
    return out;
}
}  // namespace

TEST_CASE("every strategy returns what the complete search returns, ray by ray", "[cache][exact]") {
    for (Layout layout : kLayouts) {
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            const Scene scene = testing::randomScene(layout, seed);
            const LinearSearch linear(scene);
            const std::vector<Query> queries = queryStream(scene, seed * 31);
            for (CacheKind kind : {CacheKind::Cylinder, CacheKind::Blocker, CacheKind::BlockerDirections}) {
                auto strategy = makeStrategy(kind, scene, linear);
                CacheEntry entries[kRayKinds + 2];  // one per kind and light, like a small cache tree
                Counters n, scratch;
                std::uint64_t hits = 0;
                for (const Query& q : queries) {
                    CacheEntry& e = entries[q.kind == RayKind::Shadow ? kRayKinds + q.light : int(q.kind)];
                    const Lookup l = strategy->lookup(q, e, LookupMode::Full, n);
                    const Answer truth = linear.nearest(q, scratch);
                    INFO(scene.name << " " << toString(kind) << " kind " << toString(q.kind));
                    REQUIRE(l.known);
                    REQUIRE(l.answer().object == truth.object);
                    REQUIRE(l.answer().t == truth.t);
                    hits += l.decision == Decision::Hit;
                }
                INFO(scene.name << " " << toString(kind));
                REQUIRE(hits > 0);  // the stream is coherent enough that the cache is used
            }
        }
    }
}

TEST_CASE("cheap lookups never search and never reload the entry", "[cache]") {
    const Scene scene = testing::randomScene(Layout::Overlapping, 5);
    const LinearSearch linear(scene);
    for (CacheKind kind : {CacheKind::Cylinder, CacheKind::Blocker}) {
        auto strategy = makeStrategy(kind, scene, linear);
        CacheEntry e;
        Counters n;
        const Query q{{scene.camera.from, glm::normalize(scene.camera.at - scene.camera.from)}, kNoHit, {}, RayKind::Primary, -1};
        const Lookup cold = strategy->lookup(q, e, LookupMode::CheapOnly, n);
        REQUIRE_FALSE(cold.known);
        REQUIRE(cold.reason == MissReason::Cold);
        REQUIRE(n.completeSearches == 0);
        REQUIRE(e.state == CacheEntry::State::Empty);
        const Lookup full = strategy->lookup(q, e, LookupMode::Full, n);
        REQUIRE(full.searched);
        REQUIRE(n.completeSearches == 1);
        const Lookup again = strategy->lookup(q, e, LookupMode::CheapOnly, n);
        REQUIRE(again.known);
        REQUIRE(again.decision == Decision::Hit);
        REQUIRE(again.answer() == full.answer());
    }
}

namespace {
/// A complete search that counts the searches made through it, whatever the strategy's
/// own counters say
class CountingSearch final : public CompleteSearch {
public:
    CountingSearch(const Scene& scene, const CompleteSearch& inner) : CompleteSearch(scene), inner_(inner) {}
    Answer nearest(const Query& q, Counters& n) const override {
        ++searches;
        return inner_.nearest(q, n);
    }
    std::string name() const override { return inner_.name(); }
    void cull(SphereCull& c) const override { inner_.cull(c); }
    double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                     double stopBelow = -kNoHit, int* nearest = nullptr) const override {
        return inner_.clearance(a, b, skip, skipToo, cap, stopBelow, nearest);
    }
    double nearRadius() const override { return inner_.nearRadius(); }
    bool cheap() const override { return inner_.cheap(); }
    mutable std::uint64_t searches = 0;

private:
    const CompleteSearch& inner_;
};
}  // namespace

TEST_CASE("CheapOnly never searches, in front of every search and with every cache", "[cache][cheap]") {
    // As the breadth-first order does: each ray is first asked cheaply, then (when its
    // turn comes) fully. Large scenes, so that blocker+ meets long lists in front of a
    // grid or hierarchy (which it searches past) and tiles large polygons.
    for (Layout layout : {Layout::Overlapping, Layout::Transparent, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 7, 120);
        const LinearSearch linear(scene);
        const std::vector<Query> queries = queryStream(scene, 77);
        for (AccelKind accel : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh}) {
            const auto inner = makeCompleteSearch(accel, scene);
            const CountingSearch search(scene, *inner);
            for (CacheKind kind : allCacheKinds()) {
                auto strategy = makeStrategy(kind, scene, search);
                INFO(scene.name << " " << toString(accel) << " " << toString(kind));
                if (!strategy->caches()) {
                    // Without a cache every lookup searches: the orders never ask it cheaply
                    CHECK(kind == CacheKind::None);
                    continue;
                }
                CacheEntry entries[kRayKinds + 2];
                Counters n, scratch;
                std::uint64_t known = 0, deferred = 0, fullSearches = 0;
                for (const Query& q : queries) {
                    CacheEntry& e = entries[q.kind == RayKind::Shadow ? kRayKinds + q.light : int(q.kind)];
                    const Answer truth = linear.nearest(q, scratch);
                    const std::uint64_t before = search.searches, counted = n.completeSearches;
                    const Lookup cheap = strategy->lookup(q, e, LookupMode::CheapOnly, n);
                    REQUIRE(search.searches == before);
                    REQUIRE(n.completeSearches == counted);
                    REQUIRE_FALSE(cheap.searched);
                    if (cheap.known) {
                        ++known;
                        REQUIRE(cheap.answer() == truth);
                        continue;
                    }
                    ++deferred;
                    const Lookup full = strategy->lookup(q, e, LookupMode::Full, n);
                    REQUIRE(full.known);
                    REQUIRE(full.answer() == truth);
                    // The strategy's own count of complete searches is the true one
                    fullSearches += search.searches - before;
                    REQUIRE(n.completeSearches - counted == search.searches - before);
                    REQUIRE(full.searched == (search.searches > before));
                }
                // Both paths ran: the stream is coherent enough for cheap answers, and
                // not so coherent that nothing is deferred
                CHECK(known > 0);
                CHECK(deferred > 0);
                // blocker+dir answers every miss from a direction list in front of the scan
                if (kind == CacheKind::BlockerDirections && accel == AccelKind::Linear) {
                    CHECK(fullSearches == 0);
                    CHECK(n.directionSearches > 0);
                } else {
                    CHECK(fullSearches > 0);
                }
            }
        }
    }
}

TEST_CASE("images are identical across caches and orders on random scenes, --verify agrees",
          "[cache][exact][image]") {
    for (Layout layout : kLayouts) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            auto scene = std::make_shared<const Scene>(testing::randomScene(layout, seed));
            RenderOptions base;
            base.band = 8;
            RenderSession reference(scene, base);
            reference.run();
            const auto expected = reference.image().rgb8();
            for (CacheKind cache : {CacheKind::None, CacheKind::Cylinder, CacheKind::Blocker}) {
                for (OrderKind order : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst}) {
                    RenderOptions o = base;
                    o.cache = cache;
                    o.order = order;
                    o.verify = true;
                    RenderSession s(scene, o);
                    s.run();
                    INFO(scene->name << " " << toString(cache) << " " << toString(order));
                    REQUIRE(s.counters().verifyDisagreements == 0);
                    REQUIRE(s.image().rgb8() == expected);
                    REQUIRE(s.counters().totalRays() == reference.counters().totalRays());
                }
            }
        }
    }
}


TEST_CASE("blocker lists are built lazily, once per pair met", "[cache][blocker]") {
    auto scene = std::make_shared<const Scene>(testing::randomScene(Layout::Overlapping, 9));
    RenderOptions o;
    o.cache = CacheKind::Blocker;
    RenderSession s(scene, o);
    s.run();
    const Counters& n = s.counters();
    const BlockerLists* lists = s.strategy().blockerLists();
    REQUIRE(lists != nullptr);
    REQUIRE(n.blockerListsBuilt == lists->size());
    // no O(n^3) precomputation: far fewer lists than (sites)^2
    const int sites = lists->sites();
    REQUIRE(sites == scene->size() + 1 + int(scene->lights.size()));
    REQUIRE(n.blockerListsBuilt < std::size_t(sites * sites));
    // (What each list holds is checked against a second computation of the hull in
    // tests/instructor/test_hull_oracles.cpp, which the student edition leaves out)
    std::uint64_t found = 0, longest = 0, listed = 0;
    for (int origin = 0; origin < sites; ++origin)
        for (int target = 0; target < sites; ++target) {
            const std::vector<int>* list = lists->find(origin, target);
            if (!list) continue;
            ++found;
            longest = std::max<std::uint64_t>(longest, list->size());
            listed += list->size();
        }
    REQUIRE(found == n.blockerListsBuilt);
    REQUIRE(longest == n.blockerListMax);
    REQUIRE(listed > found);  // the lists are not empty
    // The linear search finds the objects of a hull through its hierarchy of bounding
    // spheres: fewer measured than a scan, which measures every object once per list
    const std::uint64_t objects = std::uint64_t(scene->size());
    REQUIRE(n.hullTests > 0);
    REQUIRE(n.hullTests < n.blockerListsBuilt * (objects - 1));

    // A pair met again finds its list: nothing built, no hull tested
    const LinearSearch linear(*scene, LinearSearch::Regions::Scan);
    BlockerLists fresh(*scene, linear);
    Counters first, again;
    const BlockerList& built = fresh.get(fresh.eyeSite(), 0, first);
    REQUIRE(first.blockerListsBuilt == 1);
    REQUIRE(first.hullTests >= objects - 1);
    REQUIRE(first.hullTests <= objects);
    REQUIRE(&fresh.get(fresh.eyeSite(), 0, again) == &built);
    REQUIRE(again.blockerListsBuilt == 0);
    REQUIRE(again.hullTests == 0);
    REQUIRE(fresh.size() == 1);

    // A path's memo of its last list answers only for that list's own pair
    std::uint32_t memo = std::uint32_t(-1);
    for (int round = 0; round < 2; ++round)
        for (int target = 0; target < 4; ++target)
            for (int repeat = 0; repeat < 2; ++repeat) {
                const BlockerList& list = fresh.get(fresh.eyeSite(), target, memo, again);
                REQUIRE(&list == &fresh.get(fresh.eyeSite(), target, again));
                REQUIRE(list.origin == fresh.eyeSite());
                REQUIRE(list.target == target);
            }
    REQUIRE(fresh.size() == 4);
    REQUIRE(again.blockerListsBuilt == 3);

    // In front of a cheap search (blocker+), a pair met once gets no list: it is bypassed
    // (searched), and its list is built when it is met again, once
    const BoundingVolumeHierarchy bvh(*scene);
    REQUIRE(bvh.cheap());
    BlockerLists later(*scene, bvh, true, true);
    Counters once, twice, thrice;
    std::uint32_t none = std::uint32_t(-1);
    const BlockerList& met = later.get(later.eyeSite(), 0, none, once);
    REQUIRE(met.bypass);
    REQUIRE(met.ids.empty());
    REQUIRE(once.blockerListsBuilt == 0);
    REQUIRE(once.hullTests == 0);
    REQUIRE(later.find(later.eyeSite(), 0) == nullptr);
    REQUIRE(later.builds() == 0);
    const BlockerList& second = later.get(later.eyeSite(), 0, none, twice);
    REQUIRE(&second == &met);
    REQUIRE(twice.blockerListsBuilt == 1);
    REQUIRE(twice.hullTests > 0);
    REQUIRE(later.builds() == 1);
    REQUIRE(later.find(later.eyeSite(), 0) != nullptr);
    // The same objects as the list built at once in front of the linear scan
    REQUIRE(second.bypass == (built.ids.size() > kLongList));
    if (!second.bypass) {
        std::vector<int> a = second.ids, b = built.ids;
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        REQUIRE(a == b);
    }
    later.get(later.eyeSite(), 0, none, thrice);
    REQUIRE(thrice.blockerListsBuilt == 0);
    REQUIRE(later.size() == 1);
}

TEST_CASE("a cylinder of safety is measured only once a ray may fit in it", "[cache][cylinder]") {
    const Scene scene = testing::randomScene(Layout::Tangent, 3);
    const LinearSearch linear(scene);
    const double slack = 1e-9 * scene.extent();
    auto strategy = makeStrategy(CacheKind::Cylinder, scene, linear);
    // A ray leaving a sphere that hits nothing, with room around it
    int checked = 0;
    for (const Query& q : queryStream(scene, 5)) {
        if (q.kind != RayKind::Reflection || q.origin.inside || checked >= 20) continue;
        CacheEntry e;
        Counters n;
        const Lookup first = strategy->lookup(q, e, LookupMode::Full, n);
        if (first.answer().object >= 0) continue;
        const SafetyCylinder kept = e.cylinder;
        const double radius = linear.clearance(kept.a, kept.b, -1, q.origin.object, kNoHit) - slack;
        if (!(radius > 0.0)) continue;
        REQUIRE(e.pending);
        // A ray from the same point turned far away strays farther than the nearest object
        // lies: ruled out, nothing measured in full, the cylinder still pending
        Query turned = q;
        turned.ray.d = glm::normalize(glm::reflect(q.ray.d, glm::normalize(q.ray.o - scene.objects[q.origin.object].bound.c)) + 0.3 * q.ray.d);
        const double strays = std::max(kept.distance(turned.ray.o), kept.distance(turned.ray.at(1.0)));
        if (!(strays > radius)) continue;
        const Lookup away = strategy->lookup(turned, e, LookupMode::CheapOnly, n);
        REQUIRE_FALSE(away.known);
        REQUIRE(away.reason == MissReason::LeftCylinder);
        REQUIRE(n.cylindersRuledOut == 1);
        REQUIRE(n.cylindersBuilt == 0);
        REQUIRE(e.pending);
        REQUIRE(e.cylinderBelow >= radius);
        // The ray itself fits: now the cylinder is built, with the radius of a full measure
        const Lookup again = strategy->lookup(q, e, LookupMode::CheapOnly, n);
        REQUIRE(again.known);
        REQUIRE(again.decision == Decision::Hit);
        REQUIRE(n.cylindersBuilt == 1);
        REQUIRE_FALSE(e.pending);
        REQUIRE(e.cylinder.radius == radius);
        REQUIRE(n.completeSearches == 1);
        ++checked;
    }
    REQUIRE(checked == 20);

    // Whole renders: the same image as no cache, and most cylinders never measured
    auto cube = std::make_shared<const Scene>(loadScene("cube:4"));
    RenderOptions base;
    base.width = base.height = 48;
    RenderSession reference(cube, base);
    reference.run();
    for (CacheKind cache : {CacheKind::Cylinder, CacheKind::Blocker})
        for (OrderKind order : {OrderKind::Scanline, OrderKind::BreadthFirst}) {
            RenderOptions o = base;
            o.cache = cache;
            o.order = order;
            RenderSession s(cube, o);
            s.run();
            INFO(toString(cache) << " " << toString(order));
            REQUIRE(s.image().rgb8() == reference.image().rgb8());
            REQUIRE(s.counters().cylindersBuilt > 0);
            REQUIRE(s.counters().cylindersRuledOut > s.counters().cylindersBuilt);
        }
}

TEST_CASE("the cache tree flushes the entries beneath a miss", "[cache][tree]") {
    CacheTree tree;
    const int refl = tree.child(0, RayKind::Reflection);
    const int shadow = tree.child(refl, RayKind::Shadow, 1);
    const int refr = tree.child(0, RayKind::Refraction);
    REQUIRE(tree.child(0, RayKind::Reflection) == refl);
    REQUIRE(tree.label(shadow) == "eye/reflection/shadow 2");
    for (int n : {0, refl, shadow, refr}) tree.entry(n).state = CacheEntry::State::Loaded;
    tree.flushBelow(refl);
    REQUIRE(tree.entry(0).state == CacheEntry::State::Loaded);
    REQUIRE(tree.entry(refl).state == CacheEntry::State::Loaded);
    REQUIRE(tree.entry(shadow).state == CacheEntry::State::Flushed);
    REQUIRE(tree.entry(refr).state == CacheEntry::State::Loaded);
    tree.flushBelow(0);
    REQUIRE(tree.entry(refl).state == CacheEntry::State::Flushed);
    REQUIRE(tree.entry(refr).state == CacheEntry::State::Flushed);
    // A path made later, two steps beneath the eye, is flushed with them; the eye's own is not
    const int deep = tree.child(refr, RayKind::Reflection);
    for (int n : {0, refl, shadow, refr, deep}) tree.entry(n).state = CacheEntry::State::Loaded;
    tree.flushBelow(refr);
    REQUIRE(tree.entry(deep).state == CacheEntry::State::Flushed);
    REQUIRE(tree.entry(shadow).state == CacheEntry::State::Loaded);
    tree.flushBelow(0);
    REQUIRE(tree.entry(0).state == CacheEntry::State::Loaded);
    for (int n : {refl, shadow, refr, deep}) REQUIRE(tree.entry(n).state == CacheEntry::State::Flushed);
}

TEST_CASE("a tiled polygon is listed when a tile meets the hull: the tiles under it decide", "[cache][blocker][tiles]") {
    // blocker+ cuts large polygons into tiles; building a list measures only the tiles under
    // the hull (BlockerLists::tilesUnder), which must list exactly what measuring them all does
    const Scene scene = testing::randomScene(Layout::Polygons, 5, 150);
    const LinearSearch linear(scene);
    BlockerLists lists(scene, linear, true);
    const int firstTile = scene.size() + 1 + int(scene.lights.size());
    REQUIRE(lists.sites() > firstTile);  // the scene has tiled polygons
    const double tolerance = 1e-7 * scene.extent();
    Random rng(29);
    auto pick = [&](Random& r) { return r.index(scene.size()); };
    int listedTiled = 0, leftOutTiled = 0;
    for (int k = 0; k < 400; ++k) {
        const int origin = pick(rng), target = pick(rng);
        if (origin == target) continue;
        Counters n;
        const BlockerList& list = lists.get(origin, target, n);
        const Hull hull(lists.siteSphere(origin), lists.siteSphere(target));
        for (int polygon = 0; polygon < scene.size(); ++polygon) {
            if (polygon == target) continue;
            // The least gap between the hull and any tile of this polygon, every tile measured
            double gap = kNoHit;
            bool tiled = false;
            for (int site = firstTile; site < lists.sites(); ++site) {
                if (lists.siteObject(site) != polygon) continue;
                tiled = true;
                const Sphere tile = lists.siteSphere(site);
                gap = std::min(gap, hull.distance(tile.c) - tile.r);
            }
            if (!tiled) continue;
            const bool listed = std::count(list.ids.begin(), list.ids.end(), polygon) == 1;
            INFO("pair " << origin << " -> " << target << " polygon " << polygon << " gap " << gap);
            if (gap > tolerance) REQUIRE_FALSE(listed);
            const bool boundMeets = hull.distance(scene.objects[polygon].bound.c) - scene.objects[polygon].bound.r < -tolerance;
            if (gap < -tolerance && boundMeets) REQUIRE(listed);
            listedTiled += listed;
            leftOutTiled += !listed && boundMeets;
        }
    }
    // Both outcomes occur: tiles keep polygons whose bounding sphere meets the hull out
    REQUIRE(listedTiled > 20);
    REQUIRE(leftOutTiled > 20);
}

TEST_CASE("a direction list holds every object a ray leaving its site in its cell can hit", "[cache][directions]") {
    // Rays leave random points of each site (an object's surface, a tile of a large polygon,
    // the eye) in random directions; every object the ray hits, anywhere along it, must be
    // on the list of its site and cell
    Random rng(11);
    const Uniform u{-1.0, 1.0};
    const std::string rings = std::string(RAYCACHE_SCENES_DIR) + "/rings2.nff";
    for (const std::string& spec : {std::string("cube:4"), std::string("balls:1"), std::string("glass"), rings}) {
        const Scene scene = loadScene(spec);
        const LinearSearch linear(scene);
        const BlockerLists sites(scene, linear, true);
        DirectionLists directions(scene, linear, sites);
        Counters n;
        std::uint64_t checked = 0, listed = 0, entries = 0;
        for (int ray = 0; ray < 6000; ++ray) {
            const int id = ray % (scene.size() + 1) - 1;  // -1: the eye
            Vec3 o = scene.camera.from;
            RayOrigin origin;
            if (id >= 0) {
                // A point of the object's bounding sphere, on the surface for a sphere
                const Sphere b = scene.objects[id].bound;
                const Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
                o = b.c + dir * (scene.objects[id].shape == Shape::Sphere ? b.r : b.r * std::abs(u(rng)));
                if (scene.objects[id].shape == Shape::Polygon) {
                    // onto the polygon's plane, so a tile holds it
                    const Polygon& poly = scene.polygons[scene.objects[id].index];
                    o -= glm::dot(o - poly.vertices[0], poly.normal) * poly.normal;
                    if (glm::length(o - b.c) > b.r) continue;
                }
                origin = {id, false};
            }
            const Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            const int site = id >= 0 ? sites.pointSite(id, o) : sites.eyeSite();
            std::uint32_t memo = std::uint32_t(-1);
            const DirectionList& list = directions.get(site, d, memo, n);
            REQUIRE(list.origin == site);
            REQUIRE(list.target == DirectionLists::cell(d, site == sites.eyeSite() ? DirectionLists::kEyeCellsPerSide
                                                                                     : DirectionLists::kCellsPerSide));
            REQUIRE_FALSE(list.bypass);
            ++listed;
            entries += list.ids.size();
            REQUIRE(std::is_sorted(list.reach.begin(), list.reach.end()));
            const Ray r{o, d};
            for (int j = 0; j < scene.size(); ++j) {
                if (j == id) continue;
                const double t = scene.intersect(r, j, origin);
                if (!(t < kNoHit)) continue;
                ++checked;
                INFO(spec << ": ray " << ray << " from site " << site << " hits object " << j << " at " << t);
                const auto at = std::find(list.ids.begin(), list.ids.end(), j);
                REQUIRE(at != list.ids.end());
                // No ray reaches it sooner than its reach
                REQUIRE(list.reach[std::size_t(at - list.ids.begin())] <= t);
            }
        }
        INFO(spec);
        REQUIRE(checked > 100);
        // Lists are short, and built once per (site, cell) met
        REQUIRE(listed > 0);
        REQUIRE(double(entries) / double(listed) < 0.5 * scene.size());
        REQUIRE(n.directionListsBuilt == directions.size());
        REQUIRE(directions.size() < 6000);
    }
}

namespace {
/// A square render in breadth-first order.
RenderOptions breadthFirst(int size, CacheKind cache, AccelKind accel) {
    RenderOptions o;
    o.width = o.height = size;
    o.order = OrderKind::BreadthFirst;
    o.cache = cache;
    o.accel = accel;
    return o;
}
}  // namespace

TEST_CASE("blocker+dir answers its misses from direction lists, each built once", "[cache][directions]") {
    auto scene = std::make_shared<const Scene>(loadScene("cube:5"));
    RenderOptions o = breadthFirst(96, CacheKind::BlockerPlus, AccelKind::Linear);
    RenderSession plus(scene, o);
    plus.run();
    o.cache = CacheKind::BlockerDirections;
    RenderSession dir(scene, o);
    dir.run();
    const Counters& a = plus.counters();
    const Counters& b = dir.counters();
    REQUIRE(a.directionSearches == 0);
    REQUIRE(b.directionSearches > 0);
    // Nearly every complete search of blocker+ becomes a direction search
    REQUIRE(b.completeSearches * 20 < a.completeSearches);
    REQUIRE(b.intersectionTests * 3 < a.intersectionTests);
    // Lists are reused: several misses per list built
    REQUIRE(b.directionListsBuilt * 3 < b.directionSearches);
    // No deferral: a miss is answered at once
    REQUIRE(b.deferrals == 0);
    REQUIRE(plus.image().rgb8() == dir.image().rgb8());
    // In front of a hierarchy, no lists: it is blocker+
    o.accel = AccelKind::Bvh;
    RenderSession bvh(scene, o);
    bvh.run();
    REQUIRE(bvh.counters().directionListsBuilt == 0);
}

TEST_CASE("blocker+ in front of a hierarchy steps aside on paths whose rays mostly search", "[cache][aside]") {
    // A sphereflake's small spheres: most rays of most paths miss the cached object, and a
    // search through the hierarchy makes two or so tests
    auto flake = std::make_shared<const Scene>(loadScene("balls:3"));
    RenderOptions o = breadthFirst(128, CacheKind::BlockerPlus, AccelKind::Bvh);
    RenderSession aside(flake, o);
    aside.run();
    const Counters& n = aside.counters();
    REQUIRE(n.steppedAside > n.totalRays() / 2);
    REQUIRE(n.steppedAside <= n.completeSearches);
    // The paper's cache and the linear scan never step aside
    o.cache = CacheKind::Blocker;
    RenderSession paper(flake, o);
    paper.run();
    REQUIRE(paper.counters().steppedAside == 0);
    REQUIRE(paper.image().rgb8() == aside.image().rgb8());
    o.cache = CacheKind::BlockerPlus;
    o.accel = AccelKind::Linear;
    o.width = o.height = 32;
    RenderSession linear(flake, o);
    linear.run();
    REQUIRE(linear.counters().steppedAside == 0);
    // Where the cache answers most rays, few step aside: cube:4's large spheres
    auto cube = std::make_shared<const Scene>(loadScene("cube:4"));
    o.accel = AccelKind::Bvh;
    o.width = o.height = 128;
    RenderSession kept(cube, o);
    kept.run();
    REQUIRE(kept.counters().steppedAside < kept.counters().totalRays() / 3);
    REQUIRE(kept.counters().hits > 2 * kept.counters().steppedAside);
}

TEST_CASE("a cell's quick test gives the same bits eight at a time as one at a time", "[cache][directions]") {
    // Random aims and cones, many of them on a verdict's edge (aim equal to edge -+ margin
    // up to rounding), and every count from 0 to 130: the AVX2 path (where the processor
    // has it) and the scalar one set the same bits, and the bits follow the verdicts
    Random rng(7);
    const Uniform u{-1.0, 1.0};
    std::uint64_t edges = 0;
    for (int round = 0; round < 40; ++round) {
        const std::size_t count = std::size_t(round * 3 + round % 5);
        std::vector<float> x(count), y(count), z(count), cosB(count), sinB(count);
        const Vec3 axis = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
        const double alpha = 0.5 * (u(rng) + 1.0);
        const DirectionLists::QuickCone c{float(axis.x), float(axis.y), float(axis.z), float(std::cos(alpha)),
                                          float(std::sin(alpha))};
        for (std::size_t k = 0; k < count; ++k) {
            const Vec3 v = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
            const double beta = 0.25 * (u(rng) + 1.0);
            x[k] = float(v.x), y[k] = float(v.y), z[k] = float(v.z);
            cosB[k] = float(std::cos(beta)), sinB[k] = float(std::sin(beta));
            if (k % 3 == 0) {
                // Put the aim on the edge: the sphere's angle from the axis exactly alpha + beta
                const Vec3 side = glm::normalize(glm::cross(axis, v));
                const Vec3 w = glm::normalize(std::cos(alpha + beta) * axis +
                                              std::sin(alpha + beta) * glm::cross(side, axis));
                x[k] = float(w.x), y[k] = float(w.y), z[k] = float(w.z);
            }
        }
        const std::size_t words = (count + 63) / 64;
        std::vector<std::uint64_t> maybe1(words + 1, ~0ull), sure1(words + 1, ~0ull), maybe2(words + 1),
            sure2(words + 1);
        DirectionLists::quickTest(c, x.data(), y.data(), z.data(), cosB.data(), sinB.data(), count, maybe1.data(),
                                  sure1.data(), true);
        DirectionLists::quickTest(c, x.data(), y.data(), z.data(), cosB.data(), sinB.data(), count, maybe2.data(),
                                  sure2.data(), false);
        INFO("round " << round << ", " << count << " objects");
        for (std::size_t w = 0; w < words; ++w) {
            REQUIRE(maybe1[w] == maybe2[w]);
            REQUIRE(sure1[w] == sure2[w]);
        }
        REQUIRE(maybe1[words] == ~0ull);  // nothing written past the words asked for
        for (std::size_t k = 0; k < count; ++k) {
            const float aim = x[k] * c.ax + y[k] * c.ay + z[k] * c.az, edge = c.cosA * cosB[k] - c.sinA * sinB[k];
            REQUIRE(bool(maybe2[k / 64] >> (k % 64) & 1) == (aim >= edge - 1e-4f));
            REQUIRE(bool(sure2[k / 64] >> (k % 64) & 1) == (aim >= edge + 1e-4f));
            edges += std::abs(aim - edge) < 2e-4f;
        }
    }
    REQUIRE(edges > 100);  // the edge cases were met
}

namespace {
/// A random query against `scene`: from inside the box [-4, 4]^3, or (every fourth) from an
/// object's centre as if leaving its surface; every third limited to a random tmax
Query randomQuery(const Scene& scene, Random& rng, const Uniform& u, int k) {
    Query q;
    q.origin = {k % 4 == 0 ? int(rng.index(scene.size())) : -1, false};
    q.ray = Ray{Vec3(4.0 * u(rng), 4.0 * u(rng), 4.0 * u(rng)), glm::normalize(Vec3(u(rng), u(rng), u(rng)))};
    if (q.origin.object >= 0) q.ray.o = scene.objects[q.origin.object].bound.c;
    q.tmax = k % 3 == 0 ? 2.0 + 3.0 * std::abs(u(rng)) : kNoHit;
    return q;
}
}  // namespace

TEST_CASE("packed spheres test a list as testObjectQuickly does, four at a time or one", "[cache][packed]") {
    // Random lists (spheres, polygons, the ray's own object), nearest first or not, against
    // random rays: the same nearest hit, ties included, and the same count of tests
    Random rng(42);
    const Uniform u{-1.0, 1.0};
    std::uint64_t hits = 0, cases = 0;
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        const Scene scene = testing::randomScene(layout, 7, 40);
        const PackedSpheres packed(scene);
        for (int k = 0; k < 3000; ++k) {
            // A list of distinct ids, with made-up reaches, ascending
            std::vector<int> ids;
            for (int id = 0; id < scene.size(); ++id)
                if (rng.index(3) == 0) ids.push_back(id);
            std::vector<double> reach(ids.size());
            for (std::size_t i = 0; i < ids.size(); ++i) reach[i] = 0.3 * double(i) + 0.5 * u(rng);
            std::sort(reach.begin(), reach.end());
            const Query q = randomQuery(scene, rng, u, k);
            for (const bool nearestFirst : {false, true}) {
                const double* r = nearestFirst ? reach.data() : nullptr;
                // The loop testBlockers() ran before
                Answer want;
                Counters wantN;
                for (std::size_t i = 0; i < ids.size() && (!r || r[i] <= std::min(want.t, q.tmax)); ++i)
                    testObjectQuickly(scene, q, ids[i], want, wantN);
                Answer scalar, any;
                Counters scalarN, anyN;
                packed.testNearestFirstScalar(scene, q, ids.data(), r, ids.size(), scalar, scalarN);
                packed.testNearestFirst(scene, q, ids.data(), r, ids.size(), any, anyN);
                INFO(testing::name(layout) << " case " << k << " nearest first " << nearestFirst);
                REQUIRE(scalar.object == want.object);
                REQUIRE(scalar.t == want.t);
                REQUIRE(any.object == want.object);
                REQUIRE(any.t == want.t);
                REQUIRE(scalarN.intersectionTests == wantN.intersectionTests);
                REQUIRE(anyN.intersectionTests == wantN.intersectionTests);
                hits += want.object >= 0;
                ++cases;
            }
        }
    }
    // Both outcomes occur
    REQUIRE(hits > cases / 10);
    REQUIRE(hits < cases);
}

TEST_CASE("a site's order by reach is std::sort's, ties, signs and zeros included", "[cache][directions]") {
    // The radix sort must order (reach, id) pairs exactly as std::sort does: by reach, then
    // by id, with -0.0 equal to 0.0, negative reaches first, and many ties
    Random rng(31);
    const Uniform u{-3.0, 3.0};
    ReachOrder order;
    for (int n : {0, 1, 2, 7, 64, 513}) {
        for (int round = 0; round < 20; ++round) {
            std::vector<std::pair<double, int>> pairs;
            order.clear();
            for (int id = 0; id < n; ++id) {
                double reach = u(rng);
                if (round % 4 == 1) reach = std::round(reach);  // ties
                if (round % 4 == 2) reach = id % 3 == 0 ? -0.0 : id % 3 == 1 ? 0.0 : reach * 1e-300;  // zeros, denormals
                if (round % 4 == 3) reach = id % 2 ? 1e300 * reach : reach;  // a wide range of exponents
                pairs.emplace_back(reach, id);
                order.push(reach, std::uint32_t(id));
            }
            std::sort(pairs.begin(), pairs.end());
            order.sort();
            REQUIRE(order.entries().size() == pairs.size());
            for (std::size_t k = 0; k < pairs.size(); ++k) REQUIRE(order.entries()[k].id == std::uint32_t(pairs[k].second));
        }
    }
}

TEST_CASE("the scan tests four spheres at a time as it tests one at a time", "[search][packed]") {
    // Every object of random scenes (spheres, polygons, the ray's own object; lengths that
    // are and are not a multiple of four) against random rays: testAll() keeps the same
    // nearest hit as test() over the same objects, ties included, with the same count
    Random rng(7);
    const Uniform u{-1.0, 1.0};
    std::uint64_t hits = 0, cases = 0;
    for (Layout layout : {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Polygons}) {
        for (int size : {3, 17, 40}) {
            const Scene scene = testing::randomScene(layout, 11 + std::uint64_t(size), size);
            SphereBatch batch;
            for (int id = 0; id < scene.size(); ++id) batch.add(scene, id);
            for (int k = 0; k < 2000; ++k) {
                const Query q = randomQuery(scene, rng, u, k);
                Answer want, got;
                Counters wantN, gotN;
                batch.test(scene, q, 0, batch.size(), want, wantN);
                batch.testAll(scene, q, got, gotN);
                INFO(testing::name(layout) << " size " << size << " case " << k);
                REQUIRE(got.object == want.object);
                REQUIRE(got.t == want.t);
                REQUIRE(gotN.intersectionTests == wantN.intersectionTests);
                hits += want.object >= 0;
                ++cases;
            }
        }
    }
    // Both outcomes occur
    REQUIRE(hits > cases / 10);
    REQUIRE(hits < cases);
}
