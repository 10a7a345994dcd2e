#include "search/search_registry.h"

#include "search/bounding_volume_hierarchy.h"
#include "search/embree_search.h"
#include "search/linear_search.h"
#include "search/uniform_grid.h"

namespace rc {

const Registry<SearchInfo>& searchRegistry() {
    static const Registry<SearchInfo> r = [] {
        Registry<SearchInfo> b;
        b.add({"linear", "a linear scan: every object tested",
               [](const Scene& s) { return std::make_unique<LinearSearch>(s); }});
        b.add({"grid", "a uniform grid, walked cell by cell",
               [](const Scene& s) { return std::make_unique<UniformGrid>(s); }});
        b.add({"bvh", "a bounding volume hierarchy",
               [](const Scene& s) { return std::make_unique<BoundingVolumeHierarchy>(s); }});
        b.add({"embree", "Embree (single precision: for comparison only)",
               [](const Scene& s) { return std::make_unique<EmbreeSearch>(s); }, true});
        return b;
    }();
    return r;
}

}  // namespace rc
