// Tutorial 05, a wrong answer the check must reject: beams grow through the 8 neighbours, so rays that touch
// only at a corner are merged into one beam.
#include <vector>

#include "analysis/beam_tree.h"
#include "geometry/student_code.h"

namespace rc {

int BeamTreeBuilder::labelBeams(const std::vector<Ray>& rays, std::vector<int>& index, std::vector<int>& label) const {
    for (std::size_t i = 0; i < rays.size(); ++i) index[std::size_t(rays[i].pixel)] = int(i);
    label.assign(rays.size(), -1);
    // Flood fill connected pixels with equal (origin, hit) keys
    int next = 0;
    std::vector<int> stack;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (label[i] >= 0) continue;
        label[i] = next;
        stack.push_back(int(i));
        while (!stack.empty()) {
            const Ray& q = rays[std::size_t(stack.back())];
            stack.pop_back();
            const int x = q.pixel % width_, y = q.pixel / width_;
            // The 8 neighbours: corners too
            const int nb[8][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1},
                                  {x - 1, y - 1}, {x + 1, y - 1}, {x - 1, y + 1}, {x + 1, y + 1}};
            for (const auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= width_ || n[1] >= height_) continue;
                const int r = index[std::size_t(n[1]) * width_ + n[0]];
                if (r >= 0 && label[r] < 0 && rays[r].sameBeam(rays[i])) {
                    label[r] = next;
                    stack.push_back(r);
                }
            }
        }
        ++next;
    }
    for (const Ray& r : rays) index[std::size_t(r.pixel)] = -1;
    return next;
}

BeamTreeStats BeamTreeBuilder::build() const {
    BeamTreeStats s;
    std::vector<int> index(std::size_t(width_) * height_, -1);
    std::vector<int> label;
    for (const PathLog& rays : rays_by_path_)
        if (!rays.blocks.empty()) s.nodes += labelBeams(byPixel(rays), index, label);
    s.averageRayTreeSize = double(rays_) / (double(width_) * height_);
    s.coherence = s.nodes > 0 ? s.averageRayTreeSize / double(s.nodes) : 0.0;
    return s;
}

}  // namespace rc
