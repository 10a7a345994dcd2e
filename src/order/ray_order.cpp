#include "order/ray_order.h"

#include <algorithm>

#include "order/order_registry.h"

namespace rc {

std::string_view toString(OrderKind k) {
    const auto& r = orderRegistry();
    const auto i = std::size_t(k);
    return i < r.size() ? std::string_view(r[i].name) : std::string_view("?");
}

std::optional<OrderKind> parseOrderKind(std::string_view s) {
    const int i = orderRegistry().indexOf(s);
    if (i < 0) return std::nullopt;
    return OrderKind(i);
}

std::vector<OrderKind> allOrderKinds() {
    std::vector<OrderKind> out;
    for (std::size_t i = 0; i < orderRegistry().size(); ++i) out.push_back(OrderKind(i));
    return out;
}

std::unique_ptr<RayOrder> makeOrder(OrderKind kind, int width, int rowBegin, int rowEnd, int band, int samples,
                                    bool cheapTests, RayOrder::EyeMaker makeEye) {
    return orderRegistry()[std::size_t(kind)].make(width, rowBegin, rowEnd, band, std::max(1, samples), cheapTests,
                                                   std::move(makeEye));
}

}  // namespace rc
