#pragma once
/// \file
/// \brief The tests heatmap: intersection tests per pixel on a log scale, the rule the Qt
/// window and the web page both colour with (rc::heatRamp). RayCache's own addition.
#include <cstdint>
#include <optional>
#include <vector>

#include "view/trace_recorder.h"

namespace rc {

/// The top of the tests heatmap's scale: the most tests one pixel made (at least 1). Two
/// renders side by side share the larger of their tops, so equal colours mean equal values.
double testsTop(const TraceRecorder& rec);

/// Where pixel `px` falls on the ramp, 0 to 1: log(1 + tests) / log(1 + top); nothing for
/// a pixel not traced yet (drawn black).
std::optional<double> testsHeat(const TraceRecorder& rec, int px, double top);

/// The tests heatmap of the whole image as 8-bit RGBA, rows top to bottom, untraced pixels
/// black (the page's picture; the Qt window sets the same colours in a QImage).
std::vector<std::uint8_t> testsHeatmapRgba(const TraceRecorder& rec, double top);
/// The same for pixels [begin, end) only, written at out[0..4 (end - begin)) (a band of rows:
/// the page keeps no picture-sized buffer).
void testsHeatmapRgbaInto(const TraceRecorder& rec, double top, std::uint8_t* out, int begin, int end);

}  // namespace rc
