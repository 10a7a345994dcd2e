// Exactness: every cache strategy answers every ray exactly as the complete search does.
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include <glm/geometric.hpp>

#include "random_scenes.h"
#include "render/render_session.h"
#include "search/blocker_cache.h"
#include "search/cylinder_cache.h"

using namespace rc;
using rc::testing::Layout;

namespace {
const Layout kLayouts[] = {Layout::Overlapping, Layout::Tangent, Layout::Nested, Layout::Transparent,
                           Layout::Polygons};

// Coherent query streams: eye rays sweeping, rays leaving surfaces both ways, shadow rays
std::vector<Query> queryStream(const Scene& s, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
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
            for (CacheKind kind : {CacheKind::Cylinder, CacheKind::Blocker}) {
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
                    REQUIRE(l.answer.object == truth.object);
                    REQUIRE(l.answer.t == truth.t);
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
        REQUIRE(again.answer == full.answer);
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
    const std::size_t sites = std::size_t(scene->size() + 1 + scene->lights.size());
    REQUIRE(n.blockerListsBuilt < sites * sites);
    // each list tests every object once, the target excepted
    const std::uint64_t objects = std::uint64_t(scene->size());
    REQUIRE(n.hullTests >= n.blockerListsBuilt * (objects - 1));
    REQUIRE(n.hullTests <= n.blockerListsBuilt * objects);
    REQUIRE(n.blockerListMax <= std::uint64_t(scene->size()));
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
}
