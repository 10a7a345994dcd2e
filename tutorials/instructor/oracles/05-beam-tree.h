#pragma once
// Tutorial 05's oracle (the instructor's: the student edition ships its answers as data,
// tutorials/05-beam-tree/oracle_data.txt, never this code). Included by the recording
// program's oracles.cpp (TUTORIAL_RECORD).
#include <cstdint>
#include <vector>

#include "oracles.h"

namespace tutorial::instructor {

// The oracle: brute force over the image. Every present ray starts with its own label; sweep
// after sweep, each takes the least label of its 4-neighbours with the same origin, side
// and hit, until no label changes. Then each label left is one beam.
// The labels of one path image (each pixel's least label after the sweeps)
inline std::vector<int> labelsOf(int width, int height, const PathImage& at) {
    auto same = [&](int p, int q) {
        return at[p].present && at[q].present && at[p].origin == at[q].origin && at[p].inside == at[q].inside &&
               at[p].hit == at[q].hit;
    };
    std::vector<int> label(at.size());
    for (int p = 0; p < width * height; ++p) label[p] = p;
    for (bool changed = true; changed;) {
        changed = false;
        for (int p = 0; p < width * height; ++p) {
            if (!at[p].present) continue;
            const int x = p % width, y = p / width;
            for (int q : {x > 0 ? p - 1 : -1, x + 1 < width ? p + 1 : -1, y > 0 ? p - width : -1,
                          y + 1 < height ? p + width : -1})
                if (q >= 0 && same(p, q) && label[q] < label[p]) label[p] = label[q], changed = true;
        }
    }
    return label;
}
// {beams, coherence}
inline std::vector<double> beams(int width, int height, const std::vector<PathImage>& paths) {
    std::int64_t rays = 0, beams = 0;
    for (const PathImage& at : paths) {
        const std::vector<int> label = labelsOf(width, height, at);
        for (int p = 0; p < width * height; ++p) {
            rays += at[p].present;
            beams += at[p].present && label[p] == p;
        }
    }
    const double averageRayTree = double(rays) / (double(width) * height);
    return {double(beams), beams > 0 ? averageRayTree / double(beams) : 0.0};
}

// The labels as numbers
inline std::vector<double> labels(int width, int height, const PathImage& path) {
    const std::vector<int> l = labelsOf(width, height, path);
    return std::vector<double>(l.begin(), l.end());
}

}  // namespace tutorial::instructor
