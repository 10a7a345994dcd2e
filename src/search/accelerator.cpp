#include "search/accelerator.h"

#include "search/uniform_grid.h"

namespace rc {

std::string_view toString(AccelKind k) { return k == AccelKind::Grid ? "grid" : "linear"; }

std::optional<AccelKind> parseAccelKind(std::string_view s) {
    for (AccelKind k : {AccelKind::Linear, AccelKind::Grid})
        if (toString(k) == s) return k;
    return std::nullopt;
}

std::unique_ptr<CompleteSearch> makeCompleteSearch(AccelKind kind, const Scene& scene) {
    if (kind == AccelKind::Grid) return std::make_unique<UniformGrid>(scene);
    return std::make_unique<LinearSearch>(scene);
}

}  // namespace rc
