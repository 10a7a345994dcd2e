#include "view/heatmap.h"

#include <algorithm>
#include <cmath>

#include "view/palette.h"

namespace rc {

double testsTop(const TraceRecorder& rec) {
    std::int32_t most = 1;
    const int n = rec.width() * rec.height();
    for (int px = 0; px < n; ++px) most = std::max(most, rec.testsAt(px));
    return double(most);
}

std::optional<double> testsHeat(const TraceRecorder& rec, int px, double top) {
    if (!rec.visited(px)) return std::nullopt;
    // [tests heat]
    // Logarithmic: a pixel's tests span 1 to thousands
    return std::min(1.0, std::log1p(double(rec.testsAt(px))) / std::log1p(std::max(1.0, top)));
    // [tests heat]
}

std::vector<std::uint8_t> testsHeatmapRgba(const TraceRecorder& rec, double top) {
    const int n = rec.width() * rec.height();
    std::vector<std::uint8_t> out(std::size_t(n) * 4, 0);
    testsHeatmapRgbaInto(rec, top, out.data(), 0, n);
    return out;
}

void testsHeatmapRgbaInto(const TraceRecorder& rec, double top, std::uint8_t* out, int begin, int end) {
    for (int px = begin; px < end; ++px) {
        const std::optional<double> t = testsHeat(rec, px, top);
        const Rgb c = t ? heatRamp(*t) : Rgb{};
        std::uint8_t* d = &out[std::size_t(px - begin) * 4];
        d[0] = c.r;
        d[1] = c.g;
        d[2] = c.b;
        d[3] = 255;
    }
}

}  // namespace rc
