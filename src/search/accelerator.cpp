#include "search/accelerator.h"

#include "search/search_registry.h"

namespace rc {

std::string_view toString(AccelKind k) {
    const auto& r = searchRegistry();
    const auto i = std::size_t(k);
    return i < r.size() ? std::string_view(r[i].name) : std::string_view("?");
}

std::optional<AccelKind> parseAccelKind(std::string_view s) {
    const int i = searchRegistry().indexOf(s);
    if (i < 0) return std::nullopt;
    return AccelKind(i);
}

std::unique_ptr<CompleteSearch> makeCompleteSearch(AccelKind kind, const Scene& scene) {
    return searchRegistry()[std::size_t(kind)].make(scene);
}

}  // namespace rc
