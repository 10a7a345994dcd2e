#pragma once
// Tutorial 05: the beam tree and coherence.
#include <cstdint>
#include <vector>

namespace tutorial {

// [declaration]
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
    std::int64_t beams = 0;  ///< beam-tree nodes over every path
    double coherence = 0.0;  ///< average ray-tree size / beam-tree size
};

/// Builds the beam tree of an image from its rays, path by path: 4-adjacent pixels whose
/// rays at the same path start on the same object (and side) and hit the same object
/// belong to one beam. The average ray-tree size is the number of rays (present
/// PixelRays over every path) divided by the number of pixels.
BeamStats beamTree(int width, int height, const std::vector<PathImage>& paths);
// [declaration]

}  // namespace tutorial
