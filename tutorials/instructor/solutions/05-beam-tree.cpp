// Tutorial 05, the reference solution: a flood fill per path.
#include "exercise.h"

namespace tutorial {

// [solution]
BeamStats beamTree(int width, int height, const std::vector<PathImage>& paths) {
    auto same = [](const PixelRay& a, const PixelRay& b) {
        return a.present && b.present && a.origin == b.origin && a.inside == b.inside && a.hit == b.hit;
    };
    BeamStats s;
    std::int64_t rays = 0;
    for (const PathImage& rays_at : paths) {
        std::vector<char> seen(rays_at.size(), 0);
        std::vector<int> stack;
        for (int p = 0; p < width * height; ++p) {
            if (!rays_at[p].present) continue;
            ++rays;
            if (seen[p]) continue;
            // A new beam: flood it through 4-neighbours with the same origin and hit
            ++s.beams;
            seen[p] = 1;
            stack.push_back(p);
            while (!stack.empty()) {
                const int q = stack.back();
                stack.pop_back();
                const int x = q % width, y = q / width;
                const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
                for (const auto& n : nb) {
                    if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
                    const int r = n[1] * width + n[0];
                    if (!seen[r] && same(rays_at[r], rays_at[q])) {
                        seen[r] = 1;
                        stack.push_back(r);
                    }
                }
            }
        }
    }
    const double averageRayTree = double(rays) / (double(width) * height);
    s.coherence = s.beams > 0 ? averageRayTree / double(s.beams) : 0.0;
    return s;
}
// [solution]

}  // namespace tutorial
