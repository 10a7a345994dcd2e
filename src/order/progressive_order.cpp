#include "order/progressive_order.h"

#include <algorithm>

namespace rc {

ProgressiveOrder::ProgressiveOrder(int width, int rowBegin, int rowEnd, int band, int samples, EyeMaker makeEye)
    : width_(width), height_(rowEnd), band_(band > 0 ? band : rowEnd - rowBegin), nextRow_(rowBegin),
      samples_(samples), makeEye_(std::move(makeEye)) {}

std::optional<Pick> ProgressiveOrder::next() {
    if (queue_.empty()) {
        if (nextRow_ >= height_) return std::nullopt;
        // A new band: its eye rays first
        const int end = std::min(height_, nextRow_ + band_);
        for (int p = nextRow_ * width_; p < end * width_; ++p)
            for (int k = 0; k < samples_; ++k) makeEye_(p, k, queue_.emplace_back());
        nextRow_ = end;
        peak_ = std::max(peak_, queue_.size());
    }
    // It stays in front until it is traced
    return Pick{&queue_.front(), LookupMode::Full};
}

void ProgressiveOrder::committed(const RayTask&, Decision, std::vector<RayTask>& children) {
    queue_.pop_front();
    for (RayTask& c : children) queue_.push_back(std::move(c));
    peak_ = std::max(peak_, queue_.size());
}

}  // namespace rc
