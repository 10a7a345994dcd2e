// The instructor's test of blocker+dir's cells of directions: it finds a direction inside each
// cell from the cell's number (the centre of its square on its cube face), which is part of
// tutorial 07's challenge (search/direction_lists.cpp's cells are a solution region), so the
// student edition leaves this folder out
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

#include <glm/geometric.hpp>

#include "scene/builtin_scenes.h"
#include "search/blocker_lists.h"
#include "search/direction_lists.h"
#include "search/linear_search.h"

using namespace rc;

TEST_CASE("a direction list picked from its site's order is the list the cull finds and sorts", "[cache][directions]") {
    // Every cell of every object and tile site, and a sample of the eye's: the same objects
    // in the same order with the same reaches, whichever way the list was built
    const std::string rings = std::string(RAYCACHE_SCENES_DIR) + "/rings2.nff";
    for (const std::string& spec : {std::string("cube:4"), std::string("balls:2"), std::string("glass"), rings}) {
        const Scene scene = loadScene(spec);
        const LinearSearch linear(scene);
        const BlockerLists sites(scene, linear, true);
        DirectionLists picked(scene, linear, sites), culled(scene, linear, sites, false);
        Counters n;
        std::uint64_t compared = 0, entries = 0;
        for (int site = 0; site < sites.sites(); ++site) {
            if (sites.siteObject(site) < 0 && site != sites.eyeSite()) continue;  // lights have no direction lists
            const bool eye = site == sites.eyeSite();
            const int side = eye ? DirectionLists::kEyeCellsPerSide : DirectionLists::kCellsPerSide;
            for (int cell = 0; cell < 6 * side * side; cell += eye ? 7 : 1) {
                // A direction inside the cell: its square's centre on its face
                const int face = cell / (side * side), i = cell / side % side, j = cell % side;
                Vec3 d{0.0};
                d[face / 2] = face % 2 ? -1.0 : 1.0;
                d[(face / 2 + 1) % 3] = -1.0 + (2.0 * i + 1.0) / side;
                d[(face / 2 + 2) % 3] = -1.0 + (2.0 * j + 1.0) / side;
                d = glm::normalize(d);
                REQUIRE(DirectionLists::cell(d, side) == cell);
                std::uint32_t m1 = std::uint32_t(-1), m2 = std::uint32_t(-1);
                const DirectionList& a = picked.get(site, d, m1, n);
                const DirectionList& b = culled.get(site, d, m2, n);
                INFO(spec << ": site " << site << " cell " << cell);
                REQUIRE(std::ranges::equal(a.ids, b.ids));
                REQUIRE(std::ranges::equal(a.reach, b.reach));
                ++compared;
                entries += a.ids.size();
            }
        }
        INFO(spec);
        REQUIRE(compared > 100);
        REQUIRE(entries > compared);  // the lists compared are not all empty
    }
}
