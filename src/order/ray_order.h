#pragma once
/// \file
/// \brief The order in which rays are traced: a strategy of its own, usable with any cache.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "search/cache_strategy.h"
#include "trace/ray_task.h"

namespace rc {

/// Which order visits the rays.
enum class OrderKind {
    Scanline,     ///< pixel after pixel, each pixel's ray tree depth first
    Progressive,  ///< all eye rays, then all rays of depth 2, ... (the paper's conclusion)
    BreadthFirst, ///< seed fill of each ray-tree path: one coherent region after another
};
/// The registered name of an order (order/order_registry.h; "?" for a kind never registered).
std::string_view toString(OrderKind k);
std::optional<OrderKind> parseOrderKind(std::string_view s);
/// Every registered order, in the order menus list them.
std::vector<OrderKind> allOrderKinds();

/// The next ray to trace and how far its lookup may go. The task stays where the order
/// keeps it, unmoved until the order hears what became of it (committed() or
/// deferred()): handing out a copy cost a store of a whole task per ray, and its reload.
struct Pick {
    const RayTask* task = nullptr;
    LookupMode mode = LookupMode::Full;
};

/// A pixel on the breadth-first frontier, for display.
struct FrontierView {
    std::vector<int> queued;    ///< pixels waiting in the fill queue
    std::vector<int> deferred;  ///< pixels whose cheap test failed: seeds of later regions
    int path = -1;              ///< the ray-tree path being filled
    std::int64_t region = 0;    ///< regions begun so far
};

/// Hands out rays one at a time and learns what became of them.
class RayOrder {
public:
    /// `makeEye(pixel, sample, t)` makes the eye ray of a pixel's sample in `t`, a task just
    /// constructed where the order keeps it (see primaryTask()).
    using EyeMaker = std::function<void(int pixel, int sample, RayTask& t)>;
    virtual ~RayOrder() = default;
    virtual OrderKind kind() const = 0;
    /// The next ray, or nothing when the image is done.
    virtual std::optional<Pick> next() = 0;
    /// The ray last picked was traced; `children` are the rays it spawned. `task` is the
    /// picked task itself: the order may drop it here, so it is not read after.
    virtual void committed(const RayTask& task, Decision d, std::vector<RayTask>& children) = 0;
    /// The ray last picked could not be answered cheaply: it waits.
    virtual void deferred(const RayTask&) {}
    /// Largest number of rays queued at once (tasks held for later).
    virtual std::size_t queuePeak() const = 0;
    /// Coherent regions begun (breadth-first), else 0.
    virtual std::int64_t regions() const { return 0; }
    /// Does a miss at a path flush the entries beneath it? Only when a pixel's ray tree is
    /// traced depth first: then the children's next rays really do start elsewhere.
    virtual bool flushesChildren() const { return false; }
    virtual FrontierView frontier() const { return {}; }
    /// Let its queues grow as they fill instead of making room for a band of rays up front
    /// (RenderOptions::reserveRays). Before the first next().
    virtual void roomAsNeeded() {}

    // [order-checkpoint]
    /// A copy of the order as it is now: what it has handed out, queued and deferred. For
    /// checkpoints of a stepping render; the copy is a value, never asked for rays.
    virtual std::unique_ptr<RayOrder> clone() const = 0;
    /// Becomes the order `saved` (a clone() of an order of the same kind and image) was,
    /// keeping its own EyeMaker: the eye rays it makes are still this render's.
    virtual void restore(const RayOrder& saved) = 0;
    /// Bytes its queues hold (for the memory a checkpoint takes).
    virtual std::size_t heldBytes() const = 0;
    // [order-checkpoint]

protected:
    /// restore() for a final order: copy assignment from `saved`, the EyeMaker kept.
    template <class Order>
    static void assignKeepingEye(Order& self, const RayOrder& saved) {
        EyeMaker eye = std::move(self.makeEye_);
        self = dynamic_cast<const Order&>(saved);
        self.makeEye_ = std::move(eye);
    }
};

/// Makes an order for the scanlines [rowBegin, rowEnd) of an image `width` wide. `band` is
/// the number of scanlines breadth-first and progressive orders work on at a time (0: all).
/// `samples`: eye rays per pixel (distributed ray tracing's pixel samples; each has its
/// own eye path). `cheapTests`: whether to ask the cache cheaply first and defer what it
/// cannot answer (defersMisses(), order/deferral_policy.h; never with no cache): else every ray is
/// asked fully when its turn comes.
std::unique_ptr<RayOrder> makeOrder(OrderKind kind, int width, int rowBegin, int rowEnd, int band, int samples,
                                    bool cheapTests, RayOrder::EyeMaker makeEye);

}  // namespace rc
