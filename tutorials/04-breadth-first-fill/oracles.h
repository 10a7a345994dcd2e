#pragma once
// Tutorial 04's oracle: how many regions a fill must seed. Its answers are data
// (oracle_data.txt, oracle_data.h), recorded by the instructor's oracle, a brute-force
// count over the image.
#include <vector>

namespace tutorial {
/// The connected pieces of pixels with equal key (4-neighbours) in each band of `band`
/// rows (0, or more than the height: one band), summed over the bands.
long oracleRegions(int width, int height, int band, const std::vector<int>& key);
}  // namespace tutorial
