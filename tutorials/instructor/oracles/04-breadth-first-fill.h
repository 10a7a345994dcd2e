#pragma once
// Tutorial 04's oracle (the instructor's: the student edition ships its answers as data,
// tutorials/04-breadth-first-fill/oracle_data.txt, never this code). Included by the
// recording program's oracles.cpp (TUTORIAL_RECORD).
#include <algorithm>
#include <vector>

namespace tutorial::instructor {

// The oracle: how many regions a fill must seed. Each band is filled on its own, and a
// region is everything the cache answers from one seed: the pixels of the band with the
// seed's key that 4-neighbours join to it. So the count is the number of such connected
// pieces of every band, found by brute force: every pixel starts with its own label, and
// sweep after sweep each takes the least label of its 4-neighbours in the band with the same
// key, until none changes.
inline long countRegions(int width, int height, int band, const std::vector<int>& key) {
    if (band <= 0 || band > height) band = height;
    std::vector<int> label(std::size_t(width) * height);
    for (int p = 0; p < width * height; ++p) label[p] = p;
    long regions = 0;
    for (int top = 0; top < height; top += band) {
        const int bottom = std::min(height, top + band);
        for (bool changed = true; changed;) {
            changed = false;
            for (int y = top; y < bottom; ++y)
                for (int x = 0; x < width; ++x) {
                    const int p = y * width + x;
                    for (int q : {x > 0 ? p - 1 : -1, x + 1 < width ? p + 1 : -1, y > top ? p - width : -1,
                                  y + 1 < bottom ? p + width : -1})
                        if (q >= 0 && key[q] == key[p] && label[q] < label[p]) label[p] = label[q], changed = true;
                }
        }
        for (int p = top * width; p < bottom * width; ++p) regions += label[p] == p;
    }
    return regions;
}

}  // namespace tutorial::instructor
