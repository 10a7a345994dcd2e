#pragma once
/// \file
/// \brief Progressive order: the hidden-surface view first, then deeper rays.
#include <deque>

#include "order/ray_order.h"

namespace rc {

/// "If each ray is immediately painted onto the image after it is traced, then the details
/// of the image will gradually be filled in. First, the a hidden surface view will be drawn,
/// followed by reflections and shadows at greater and greater depth" (Hanrahan 1986, its
/// words, "the a" included). A FIFO over the ray trees of a band of scanlines.
class ProgressiveOrder final : public RayOrder {
public:
    /// Scanlines [rowBegin, rowEnd), `band` at a time (0: all).
    ProgressiveOrder(int width, int rowBegin, int rowEnd, int band, int samples, EyeMaker makeEye);
    OrderKind kind() const override { return OrderKind::Progressive; }
    std::optional<Pick> next() override;
    void committed(const RayTask& task, Decision d, std::vector<RayTask>& children) override;
    std::size_t queuePeak() const override { return peak_; }
    std::unique_ptr<RayOrder> clone() const override { return std::make_unique<ProgressiveOrder>(*this); }
    void restore(const RayOrder& saved) override { assignKeepingEye(*this, saved); }
    std::size_t heldBytes() const override { return queue_.size() * sizeof(RayTask); }

private:
    friend class RayOrder;
    int width_, height_, band_;
    int nextRow_;
    int samples_;
    EyeMaker makeEye_;
    std::deque<RayTask> queue_;
    std::size_t peak_ = 0;
};

}  // namespace rc
