#include "view/overlay_registry.h"

#include <algorithm>
#include <cctype>

namespace rc {

const Registry<OverlayInfo>& overlayRegistry() {
    static const Registry<OverlayInfo> r = [] {
        Registry<OverlayInfo> b;
        b.add({"cylinder", "the cylinder of safety of the ray in focus's cache entry", {}});
        b.add({"hull", "the blocker hull of origin and target, its blockers and target", {"cone", "blocker"}});
        b.add({"frontier", "breadth-first order's queue, deferred seeds and regions", {"bfs"}});
        b.add({"misses", "each pixel's cache miss at the path in focus, coloured by reason", {"miss"}});
        b.add({"samples", "the sample rays of the pixel in focus (eye, shadow, gloss)", {"fan"}, false});
        b.add({"grid", "the pixel grid at high zoom", {}, false});
        return b;
    }();
    return r;
}

std::string overlayNamed(std::string_view word) {
    std::string w(word);
    std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const OverlayInfo& o : overlayRegistry().entries())
        if (o.name == w || std::find(o.aliases.begin(), o.aliases.end(), w) != o.aliases.end()) return o.name;
    return "";
}

}  // namespace rc
