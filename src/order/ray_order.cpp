#include "order/ray_order.h"

#include <algorithm>

#include "order/breadth_first_order.h"
#include "order/progressive_order.h"
#include "order/scanline_order.h"

namespace rc {

std::string_view toString(OrderKind k) {
    switch (k) {
        case OrderKind::Scanline: return "scanline";
        case OrderKind::Progressive: return "progressive";
        case OrderKind::BreadthFirst: return "bfs";
    }
    return "?";
}

std::optional<OrderKind> parseOrderKind(std::string_view s) {
    for (OrderKind k : {OrderKind::Scanline, OrderKind::Progressive, OrderKind::BreadthFirst})
        if (toString(k) == s) return k;
    return std::nullopt;
}

std::unique_ptr<RayOrder> makeOrder(OrderKind kind, int width, int rowBegin, int rowEnd, int band, int samples,
                                    bool cheapTests, RayOrder::EyeMaker makeEye) {
    samples = std::max(1, samples);
    switch (kind) {
        case OrderKind::Scanline:
            return std::make_unique<ScanlineOrder>(width * rowBegin, width * rowEnd, samples, std::move(makeEye));
        case OrderKind::Progressive:
            return std::make_unique<ProgressiveOrder>(width, rowBegin, rowEnd, band, samples, std::move(makeEye));
        case OrderKind::BreadthFirst:
            return std::make_unique<BreadthFirstOrder>(width, rowBegin, rowEnd, band, samples, cheapTests,
                                                       std::move(makeEye));
    }
    return nullptr;
}

}  // namespace rc
