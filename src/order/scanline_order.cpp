#include "order/scanline_order.h"

#include <algorithm>

namespace rc {

std::optional<Pick> ScanlineOrder::next() {
    if (stack_.empty()) {
        if (nextPixel_ >= pixels_) return std::nullopt;
        makeEye_(nextPixel_, nextSample_, stack_.emplace_back());
        if (++nextSample_ == samples_) {
            nextSample_ = 0;
            ++nextPixel_;
        }
    }
    // It stays on top until it is traced
    return Pick{&stack_.back(), LookupMode::Full};
}

void ScanlineOrder::committed(const RayTask&, Decision, std::vector<RayTask>& children) {
    stack_.pop_back();
    // Depth first: the children go on the stack, the first spawned on top
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack_.push_back(std::move(*it));
    peak_ = std::max(peak_, stack_.size());
}

}  // namespace rc
