#include "search/accelerator.h"

#include "search/bounding_volume_hierarchy.h"
#include "search/embree_search.h"
#include "search/linear_search.h"
#include "search/uniform_grid.h"

namespace rc {

std::string_view toString(AccelKind k) {
    switch (k) {
        case AccelKind::Linear: return "linear";
        case AccelKind::Grid: return "grid";
        case AccelKind::Bvh: return "bvh";
        case AccelKind::Embree: return "embree";
    }
    return "?";
}

std::optional<AccelKind> parseAccelKind(std::string_view s) {
    for (AccelKind k : {AccelKind::Linear, AccelKind::Grid, AccelKind::Bvh, AccelKind::Embree})
        if (toString(k) == s) return k;
    return std::nullopt;
}

std::unique_ptr<CompleteSearch> makeCompleteSearch(AccelKind kind, const Scene& scene) {
    if (kind == AccelKind::Grid) return std::make_unique<UniformGrid>(scene);
    if (kind == AccelKind::Bvh) return std::make_unique<BoundingVolumeHierarchy>(scene);
    if (kind == AccelKind::Embree) return std::make_unique<EmbreeSearch>(scene);
    return std::make_unique<LinearSearch>(scene);
}

}  // namespace rc
