#include "order/order_registry.h"

#include "order/breadth_first_order.h"
#include "order/progressive_order.h"
#include "order/scanline_order.h"

namespace rc {

const Registry<OrderInfo>& orderRegistry() {
    static const Registry<OrderInfo> r = [] {
        Registry<OrderInfo> b;
        b.add({"scanline", "pixel after pixel, each pixel's ray tree depth first",
               [](int width, int rowBegin, int rowEnd, int, int samples, bool, RayOrder::EyeMaker makeEye) {
                   return std::make_unique<ScanlineOrder>(width * rowBegin, width * rowEnd, samples,
                                                          std::move(makeEye));
               }});
        b.add({"progressive", "all eye rays, then all rays of depth 2, ... (the paper's conclusion)",
               [](int width, int rowBegin, int rowEnd, int band, int samples, bool, RayOrder::EyeMaker makeEye) {
                   return std::make_unique<ProgressiveOrder>(width, rowBegin, rowEnd, band, samples,
                                                             std::move(makeEye));
               }});
        b.add({"bfs", "breadth first: a seed fill of each ray-tree path, one coherent region after another",
               [](int width, int rowBegin, int rowEnd, int band, int samples, bool cheapTests,
                  RayOrder::EyeMaker makeEye) {
                   return std::make_unique<BreadthFirstOrder>(width, rowBegin, rowEnd, band, samples, cheapTests,
                                                              std::move(makeEye));
               }});
        return b;
    }();
    return r;
}

}  // namespace rc
