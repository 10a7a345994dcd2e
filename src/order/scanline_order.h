#pragma once
/// \file
/// \brief Scanline order: pixel after pixel, each ray tree depth first.
#include "order/ray_order.h"

namespace rc {

/// The standard ray tracer's order: row by row, and within a pixel the ray tree depth
/// first (a stack), the way a recursive tracer visits it.
class ScanlineOrder final : public RayOrder {
public:
    /// Pixels [first, end) in order, `samples` eye rays each, one ray tree after another.
    ScanlineOrder(int first, int end, int samples, EyeMaker makeEye)
        : pixels_(end), nextPixel_(first), samples_(samples), makeEye_(std::move(makeEye)) {}
    OrderKind kind() const override { return OrderKind::Scanline; }
    std::optional<Pick> next() override;
    void committed(const RayTask& task, Decision d, std::vector<RayTask>& children) override;
    std::size_t queuePeak() const override { return peak_; }
    std::unique_ptr<RayOrder> clone() const override { return std::make_unique<ScanlineOrder>(*this); }
    void restore(const RayOrder& saved) override { assignKeepingEye(*this, saved); }
    std::size_t heldBytes() const override { return stack_.size() * sizeof(RayTask); }
    bool flushesChildren() const override { return true; }

private:
    friend class RayOrder;
    int pixels_;
    int nextPixel_;
    int samples_;
    int nextSample_ = 0;
    EyeMaker makeEye_;
    std::vector<RayTask> stack_;
    std::size_t peak_ = 0;
};

}  // namespace rc
