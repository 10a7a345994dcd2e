#pragma once
// Tutorial 05's oracle: the beams a labelling of the image finds. Its answers are data
// (oracle_data.txt, oracle_data.h), recorded by the instructor's oracle, a brute-force
// labelling over the image.
#include <cstdint>
#include <vector>

namespace tutorial {

/// The ray a pixel has at one ray-tree path (eye; eye/reflection; eye/shadow 1; ...).
struct PixelRay {
    bool present = false;  ///< false: this pixel's ray tree has no ray at this path
    int origin = -1;       ///< object the ray leaves (-1: the eye)
    bool inside = false;   ///< it leaves into the object's interior (refraction)
    int hit = -1;          ///< object it hits (-1: nothing)
};

/// One ray-tree path over the whole image: `rays[y * width + x]`.
using PathImage = std::vector<PixelRay>;

/// The beam tree's size and the paper's coherence.
struct BeamStats {
    std::int64_t beams = 0;
    double coherence = 0.0;
};

/// The oracle's beams of every path (4-neighbours with the same origin, side and hit
/// join), and the coherence: the average ray tree's rays per beam.
BeamStats oracleBeams(int width, int height, const std::vector<PathImage>& paths);
/// The oracle's beam of each pixel of one path: the least pixel index in its beam (a pixel
/// without a ray at this path: its own index).
std::vector<int> oracleLabels(int width, int height, const PathImage& path);

}  // namespace tutorial
