// Tutorial 04's check: rc::BreadthFirstOrder's fill (your tutorials/04-breadth-first-fill/
// exercise.cpp in a student build), driven here as a render drives it with a cache that
// answers a pixel when its key equals the key of the region's seed, must seed or answer
// every pixel once, answer pixels from the cache only when the cache holds their key, grow
// each region through 4-neighbours, defer (not search) every pixel at a region's border,
// finish a band before the next (the queue's bound), and start exactly as many regions as
// a brute-force count of the connected pieces of equal keys in each band (data: oracles.h,
// oracle_data.txt). Then what the
// renderer makes of it: cube:4 drawn in breadth-first order equals the scanline picture.
#include <iomanip>
#include <climits>
#include <cstdio>
#include <memory>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "oracles.h"

#include "order/breadth_first_order.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "search/linear_search.h"
#include "tutorial_picture.h"
#include "tutorial_random.h"

namespace tutorial {

/// What the fill did with one pixel it picked.
enum class Step {
    Seed,    ///< a complete search (a full lookup): a new region starts here, the cache is reloaded
    Answer,  ///< the cache answered it (a cheap test): its key equals the key of the region's seed
    Defer,   ///< the cheap test failed: put aside, to be seeded or answered later
};

struct Visit {
    int pixel = 0;  ///< y * width + x
    Step step = Step::Seed;
};

/// Drives rc::BreadthFirstOrder over a width x height image of one ray per pixel, in bands
/// of `band` scanlines (0: one band), the way a render does, with a cache that answers a
/// pixel when `key[pixel]` equals the key of the last seed: the visits it makes, in order.
std::vector<Visit> seedFill(int width, int height, int band, const std::vector<int>& key) {
    rc::BreadthFirstOrder order(width, 0, height, band, 1, true, [](int pixel, int, rc::RayTask& t) {
        t.pixel = pixel;
        t.node = 0;
    });
    std::vector<Visit> visits;
    std::vector<rc::RayTask> children;  // one ray per pixel: nothing spawned
    int cached = 0;
    // A fill that never ends is wrong too: at most every pixel seeded, tried and deferred a few times
    const std::size_t most = 8 * std::size_t(width) * std::size_t(height) + 16;
    while (const std::optional<rc::Pick> pick = order.next()) {
        if (visits.size() > most) FAIL("the fill picked more than " << most << " rays for " << width * height << " pixels");
        const rc::RayTask& task = *pick->task;
        const int p = task.pixel;
        if (p < 0 || p >= width * height) FAIL("the fill picked pixel " << p << ", outside the image");
        if (pick->mode == rc::LookupMode::Full) {
            // A full lookup: the complete search reloads the cache
            const bool same = key[std::size_t(p)] == cached;
            cached = key[std::size_t(p)];
            visits.push_back({p, Step::Seed});
            order.committed(task, same ? rc::Decision::Hit : rc::Decision::Miss, children);
        } else if (key[std::size_t(p)] == cached) {
            visits.push_back({p, Step::Answer});
            order.committed(task, rc::Decision::Hit, children);
        } else {
            visits.push_back({p, Step::Defer});
            order.deferred(task);
        }
    }
    return visits;
}

}  // namespace tutorial

namespace {

using tutorial::oracleRegions;

// A small map of the image for a failure message: each pixel's key (a letter), and
// each pixel's region so far (a digit, '.' not yet visited, '*' the pixel in question)
std::string map(int width, int height, const std::vector<int>& key, const std::vector<int>& region, int at) {
    if (width > 48 || height > 48) return "(image too large to draw)";
    std::ostringstream out;
    // Catch2 wraps lines at 80 columns: the legend goes first, the two maps side by side
    out << "left: the keys, a letter each; right: your regions so far, a digit each\n"
           "(region number mod 10), '.' not yet visited; '*' marks the pixel\n";
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int p = y * width + x;
            out << (p == at ? '*' : char('a' + ((key[p] % 26) + 26) % 26));
        }
        out << "   ";
        for (int x = 0; x < width; ++x) {
            const int p = y * width + x;
            out << (p == at ? '*' : region[p] < 0 ? '.' : char('0' + region[p] % 10));
        }
        out << '\n';
    }
    return out.str();
}

struct FillReport {
    long regions = 0;
    long deferrals = 0;
};

// Checks the fill's rules and returns how many regions it seeded and how often it deferred
FillReport checkFill(int width, int height, int band, const std::vector<int>& key,
                     const std::vector<tutorial::Visit>& visits) {
    const int rows = band <= 0 || band > height ? height : band;
    auto bandOf = [&](int p) { return p / width / rows; };
    std::vector<int> region(key.size(), -1), deferredIn(key.size(), -1);
    std::vector<int> members;  // the current region's pixels
    // Deferred pixels not yet seeded or answered: they seed the next regions, before any untouched pixel
    std::vector<char> waiting(key.size(), 0);
    long waitingCount = 0;
    auto served = [&](int p) {
        if (waiting[p]) waiting[p] = 0, --waitingCount;
    };
    int current = -1, cached = 0, currentBand = 0;
    FillReport report;
    auto fail = [&](const std::string& what, int p) {
        FAIL(what << " at pixel (" << p % width << ", " << p / width << ") of a " << width << "x" << height
                  << " image worked in bands of " << rows << " rows\n"
                  << map(width, height, key, region, p));
    };
    // A region may end only when every pixel at its border was tested and deferred
    auto endRegion = [&] {
        for (int p : members) {
            const int x = p % width, y = p / width;
            // Left, right, up, down
            for (int k = 0; k < 4; ++k) {
                const int nx = x + (k == 0 ? -1 : k == 1 ? 1 : 0), ny = y + (k == 2 ? -1 : k == 3 ? 1 : 0);
                if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                const int q = ny * width + nx;
                if (bandOf(q) != currentBand || region[q] >= 0) continue;
                if (key[q] == cached)
                    fail("the region stopped growing although this neighbour has the seed's key (it must be "
                         "answered; a queued pixel asked with LookupMode::Full counts as a new seed)",
                         q);
                if (deferredIn[q] != current)
                    fail("this pixel borders the region but was never tested against the cache and deferred "
                         "(a Defer visit) while the region grew",
                         q);
            }
        }
        members.clear();
    };
    for (std::size_t i = 0; i < visits.size(); ++i) {
        const int p = visits[i].pixel;
        INFO(std::setprecision(17) << "visit " << i << " of " << visits.size());
        if (p < 0 || p >= width * height) FAIL("pixel index " << p << " is outside the image");
        if (region[p] >= 0) fail("this pixel was already seeded or answered", p);
        if (bandOf(p) < currentBand) fail("this pixel belongs to a band that was already finished", p);
        if (bandOf(p) > currentBand) {
            for (int q = currentBand * rows * width; q < std::min(height, (currentBand + 1) * rows) * width; ++q)
                if (region[q] < 0) fail("the next band started before this pixel of the band above was done", q);
            if (visits[i].step != tutorial::Step::Seed) fail("a band must start with a seed", p);
        }
        switch (visits[i].step) {
            case tutorial::Step::Seed:
                if (current >= 0) endRegion();
                if (waitingCount > 0 && !waiting[p])
                    fail("seeded a pixel no region had tried while pixels deferred at an earlier region's border "
                         "were still waiting: a new region starts from a deferred pixel (pending_), and from "
                         "an untouched one only when none is left",
                         p);
                served(p);
                currentBand = bandOf(p);
                cached = key[p];
                region[p] = ++current;
                members.push_back(p);
                break;
            case tutorial::Step::Answer:
            case tutorial::Step::Defer: {
                if (current < 0) fail("the first visit must be a seed", p);
                const bool answer = visits[i].step == tutorial::Step::Answer;
                if (answer && key[p] != cached) fail("the cache answered a pixel whose key is not the seed's", p);
                if (!answer && key[p] == cached) fail("deferred a pixel the cache could answer", p);
                // The fill grows (and defers) only through 4-neighbours already in the region
                const int x = p % width, y = p / width;
                const bool joined = (x > 0 && region[p - 1] == current) ||
                                    (x + 1 < width && region[p + 1] == current) ||
                                    (y > 0 && region[p - width] == current) ||
                                    (y + 1 < height && region[p + width] == current);
                if (!joined)
                    fail(answer ? "answered a pixel that touches no pixel of the current region"
                                : "deferred a pixel that touches no pixel of the current region",
                         p);
                if (answer) {
                    region[p] = current;
                    members.push_back(p);
                    served(p);
                } else {
                    deferredIn[p] = current;
                    ++report.deferrals;
                    if (!waiting[p]) waiting[p] = 1, ++waitingCount;
                }
                break;
            }
        }
    }
    if (current >= 0) endRegion();
    for (int p = 0; p < width * height; ++p)
        if (region[p] < 0) fail("this pixel was never seeded or answered", p);
    report.regions = current + 1;
    return report;
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

// The picture: the region map of your fill, each region in its colour, seeds white,
// pixels your fill never seeded or answered magenta
std::string drawRegions(int width, int height, const std::vector<tutorial::Visit>& visits) {
    std::vector<int> region(std::size_t(width) * height, -2);
    int current = -1;
    for (const tutorial::Visit& v : visits) {
        if (v.pixel < 0 || v.pixel >= width * height) continue;
        if (v.step == tutorial::Step::Seed) region[v.pixel] = ++current;
        else if (v.step == tutorial::Step::Answer) region[v.pixel] = current;
    }
    tutorial::Picture pic(width, height);
    for (int p = 0; p < width * height; ++p)
        pic.set(p % width, p / width, region[p] == -2 ? tutorial::Rgb{255, 0, 255} : tutorial::labelColour(region[p]));
    for (const tutorial::Visit& v : visits)
        if (v.step == tutorial::Step::Seed && v.pixel >= 0 && v.pixel < width * height)
            pic.set(v.pixel % width, v.pixel / width, {255, 255, 255});
    const std::string path = pic.save("regions", 6);
    tutorial::announcePicture("the regions of your fill on cube:3 (" + std::to_string(current + 1) +
                                  " seeds counted from Seed visits), bands of 8 rows",
                              path);
    return path;
}

}  // namespace

TEST_CASE("the fill fills random images region by region, band by band", "[tutorial04]") {
    tutorial::Random rnd(1979);  // Smith's tint fill
    long deferrals = 0;
    for (int i = 0; i < 300; ++i) {
        const int width = 1 + rnd.index(40), height = 1 + rnd.index(40);
        const int band = i % 3 == 0 ? 0 : 1 + rnd.index(height);
        const std::vector<int> key = randomKeys(rnd, width, height);
        INFO(std::setprecision(17) << "image " << i << " (" << width << "x" << height << ", bands of " << band << " rows; 0: one band)");
        const FillReport mine = checkFill(width, height, band, key, tutorial::seedFill(width, height, band, key));
        const long want = oracleRegions(width, height, band, key);
        INFO(std::setprecision(17) << "your fill seeded " << mine.regions << " regions, the oracle's count " << want
                                 << ": one per 4-connected piece of equal key in each band");
        REQUIRE(mine.regions == want);
        deferrals += mine.deferrals;
    }
    CHECK(deferrals > 0);
}

TEST_CASE("without cheap tests, every ray is asked fully when its turn comes", "[tutorial04]") {
    // A cache whose misses are not deferred (blocker+dir; blocker+ in front of a grid or a
    // BVH): the order is built with cheapTests false, and a queued pixel is asked with
    // LookupMode::Full, never deferred. One scanline a band is a walk, which the fill never
    // sees: bands of two rows or more
    tutorial::Random rnd(1981);
    for (int i = 0; i < 60; ++i) {
        const int width = 2 + rnd.index(30), height = 2 + rnd.index(30);
        const int band = 2 + rnd.index(height - 1);
        const std::vector<int> key = randomKeys(rnd, width, height);
        rc::BreadthFirstOrder order(width, 0, height, band, 1, false, [](int pixel, int, rc::RayTask& t) {
            t.pixel = pixel;
            t.node = 0;
        });
        std::vector<int> picked(key.size(), 0);
        std::vector<rc::RayTask> children;
        int cached = INT_MIN;
        long picks = 0;
        while (const std::optional<rc::Pick> pick = order.next()) {
            const int p = pick->task->pixel;
            INFO("image " << i << " (" << width << "x" << height << ", bands of " << band << " rows), pick " << picks
                          << ": pixel (" << p % width << ", " << p / width << ")");
            if (++picks > long(key.size())) FAIL("the fill picked more rays than the image has pixels");
            if (pick->mode != rc::LookupMode::Full)
                FAIL("asked with a cheap test only, although the order was made with cheapTests false "
                     "(cheapTests_): every ray must be asked fully");
            if (++picked[std::size_t(p)] > 1) FAIL("this pixel was picked twice");
            // A full lookup: the cache answers when it holds the key, else the search reloads it
            const bool same = key[std::size_t(p)] == cached;
            cached = key[std::size_t(p)];
            order.committed(*pick->task, same ? rc::Decision::Hit : rc::Decision::Miss, children);
        }
        INFO("image " << i << " (" << width << "x" << height << ", bands of " << band << " rows)");
        REQUIRE(picks == long(key.size()));
    }
}

TEST_CASE("the fill makes one complete search per region of cube:3's eye rays", "[tutorial04]") {
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
    const std::string path = drawRegions(width, height, tutorial::seedFill(width, height, 8, key));
    INFO(std::setprecision(17) << "the regions of your fill in bands of 8 rows: " << path);
    for (int band : {0, 8}) {
        INFO(std::setprecision(17) << "bands of " << band << " rows (0: one band)");
        const FillReport mine = checkFill(width, height, band, key, tutorial::seedFill(width, height, band, key));
        REQUIRE(mine.regions == oracleRegions(width, height, band, key));
    }
}

TEST_CASE("breadth-first order draws cube:4 as scanline order does", "[tutorial04]") {
    // What the renderer makes of your fill: cube:4 in breadth-first order with the cylinder
    // cache (whose misses are deferred) must equal the uncached scanline picture pixel for
    // pixel, and start a number of regions in the stated range (the reference solution's
    // count is printed below)
    const auto scene = std::make_shared<const rc::Scene>(rc::makeBuiltin("cube:4"));
    rc::RenderOptions o;
    o.width = o.height = 48;
    rc::RenderSession plain(scene, o);
    plain.run();
    o.order = rc::OrderKind::BreadthFirst;
    o.cache = rc::CacheKind::Cylinder;
    o.band = 8;
    o.verify = true;
    rc::RenderSession filled(scene, o);
    filled.run();
    int differ = 0, first = -1;
    for (int p = 0; p < 48 * 48; ++p)
        if (plain.image().value(p) != filled.image().value(p)) differ += 1, first = first < 0 ? p : first;
    const rc::Counters& n = filled.counters();
    const long long regions = filled.order().regions();
    std::printf("tutorial 04: cube:4 at 48x48, breadth-first in bands of 8 rows with the cylinder cache: %lld regions, "
                "%llu deferrals, %llu complete searches, %d pixel(s) differ from the scanline picture\n",
                regions, (unsigned long long)n.deferrals, (unsigned long long)n.completeSearches, differ);
    INFO(differ << " pixel(s) differ from the scanline picture (first: pixel " << first << "); the complete search "
                << "disagrees with " << n.verifyDisagreements << " cached answer(s); " << regions << " regions, "
                << n.deferrals << " deferrals");
    REQUIRE(n.verifyDisagreements == 0);
    REQUIRE(differ == 0);
    // The stated range: the reference solution's 3,274 regions, within a tenth (a fill that
    // seeds every ray draws the right picture too, in 5,851)
    REQUIRE(regions >= 2947);
    REQUIRE(regions <= 3601);
}
