// Tutorial 04's check: tutorial::seedFill must visit every pixel once, answer pixels from
// the cache only when the cache holds their key, grow each region through 4-neighbours,
// and start exactly as many regions as the library's rc::BreadthFirstOrder does.
#include <climits>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "exercise.h"
#include "order/breadth_first_order.h"
#include "scene/builtin_scenes.h"
#include "search/complete_search.h"
#include "tutorial_random.h"

namespace {

// Drives the library's breadth-first order over one ray-tree path (no children) with a
// one-entry cache that holds the key of the last complete search. Returns the number of
// regions it seeds.
long libraryRegions(int width, int height, const std::vector<int>& key) {
    rc::BreadthFirstOrder order(width, 0, height, 0, true, [](int pixel) {
        rc::RayTask t;
        t.pixel = pixel;
        return t;
    });
    int cached = INT_MIN;
    std::vector<rc::RayTask> none;
    while (std::optional<rc::Pick> pick = order.next()) {
        const int p = pick->task.pixel;
        const bool hit = key[p] == cached;
        if (pick->mode == rc::LookupMode::CheapOnly && !hit) {
            order.deferred(pick->task);
            continue;
        }
        if (!hit) cached = key[p];  // a full lookup that misses searches and reloads
        order.committed(pick->task, hit ? rc::Decision::Hit : rc::Decision::Miss, none);
    }
    return long(order.regions());
}

// Checks the fill's rules and returns how many regions it seeded
long checkFill(int width, int height, const std::vector<int>& key, const std::vector<tutorial::Visit>& visits) {
    REQUIRE(visits.size() == key.size());
    std::vector<int> region(key.size(), -1);
    int current = -1, cached = 0;
    for (std::size_t i = 0; i < visits.size(); ++i) {
        const int p = visits[i].pixel;
        INFO("visit " << i << ": pixel (" << p % width << ", " << p / width << ")");
        REQUIRE(p >= 0);
        REQUIRE(p < width * height);
        REQUIRE(region[p] < 0);  // every pixel once
        if (visits[i].seed) {
            cached = key[p];
            region[p] = ++current;
            continue;
        }
        REQUIRE(current >= 0);     // the first visit must seed
        REQUIRE(key[p] == cached);  // the cache can only answer its own key
        // The fill grows through 4-neighbours already in the region
        const int x = p % width, y = p / width;
        const bool joined = (x > 0 && region[p - 1] == current) || (x + 1 < width && region[p + 1] == current) ||
                            (y > 0 && region[p - width] == current) ||
                            (y + 1 < height && region[p + width] == current);
        REQUIRE(joined);
        region[p] = current;
    }
    return current + 1;
}

// Discs and boxes of random keys over a background: regions of every shape, some keys
// in several disconnected pieces
std::vector<int> randomKeys(tutorial::Random& rnd, int width, int height) {
    std::vector<int> key(std::size_t(width) * height, 0);
    const int shapes = 1 + rnd.index(12);
    for (int s = 0; s < shapes; ++s) {
        const int k = 1 + rnd.index(5);
        const double cx = rnd.uniform(0, width), cy = rnd.uniform(0, height);
        const double r = rnd.uniform(1.0, 0.4 * width);
        const bool disc = rnd.chance(0.5);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double dx = x - cx, dy = y - cy;
                if (disc ? dx * dx + dy * dy <= r * r : std::abs(dx) <= r && std::abs(dy) <= 0.5 * r)
                    key[std::size_t(y) * width + x] = k;
            }
    }
    return key;
}

}  // namespace

TEST_CASE("seedFill fills random images region by region", "[tutorial04]") {
    tutorial::Random rnd(1979);  // Smith's tint fill
    for (int i = 0; i < 300; ++i) {
        const int width = 1 + rnd.index(40), height = 1 + rnd.index(40);
        const std::vector<int> key = randomKeys(rnd, width, height);
        INFO("image " << i << " (" << width << "x" << height << ")");
        const long regions = checkFill(width, height, key, tutorial::seedFill(width, height, key));
        REQUIRE(regions == libraryRegions(width, height, key));
    }
}

TEST_CASE("seedFill makes one complete search per region of cube:3's eye rays", "[tutorial04]") {
    const rc::Scene s = rc::makeBuiltin("cube:3");
    const rc::LinearSearch search(s);
    const int width = 64, height = 64;
    const rc::RayGenerator camera(s.camera, width, height);
    std::vector<int> key(std::size_t(width) * height);
    for (int p = 0; p < width * height; ++p) {
        rc::Query q;
        q.ray = camera.primary(p % width, p / width);
        rc::Counters n;
        key[p] = search.nearest(q, n).object;  // the sphere the eye ray hits, -1 for none
    }
    const long regions = checkFill(width, height, key, tutorial::seedFill(width, height, key));
    REQUIRE(regions == libraryRegions(width, height, key));
}
