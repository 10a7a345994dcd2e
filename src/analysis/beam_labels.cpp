/// \file
/// \brief The beam tree's labels and the paper's coherence: rc::BeamTreeBuilder::labelBeams() and
/// build(), tutorial 05's hole. A student build compiles tutorials/05-beam-tree/exercise.cpp in
/// place of this file. How the rays are recorded is in analysis/beam_tree.cpp.
#include <vector>

#include "analysis/beam_tree.h"
#include "geometry/student_code.h"

namespace rc {

int BeamTreeBuilder::labelBeams(const std::vector<Ray>& rays, std::vector<int>& index, std::vector<int>& label) const {
    for (std::size_t i = 0; i < rays.size(); ++i) index[std::size_t(rays[i].pixel)] = int(i);
    label.assign(rays.size(), -1);
    // BEGIN SOLUTION 05
    // [beam-label]
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
            const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
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
    // [beam-label]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 1: one label per beam: rays of 4-adjacent pixels with the same key
    // // (Ray::sameBeam) share a label; `next` counts the beams. `index` maps a pixel
    // // to its ray (-1: none). The stub gives every ray a beam of its own.
    // notYet(5);
    // int next = 0;
    // for (std::size_t i = 0; i < rays.size(); ++i) label[i] = next++;
    // END STUB
    for (const Ray& r : rays) index[std::size_t(r.pixel)] = -1;
    return next;
}

BeamTreeStats BeamTreeBuilder::build() const {
    BeamTreeStats s;
    std::vector<int> index(std::size_t(width_) * height_, -1);
    std::vector<int> label;
    for (const PathLog& rays : rays_by_path_)
        if (!rays.blocks.empty()) s.nodes += labelBeams(byPixel(rays), index, label);
    // BEGIN SOLUTION 05
    // [coherence]
    s.averageRayTreeSize = double(rays_) / (double(width_) * height_);
    s.coherence = s.nodes > 0 ? s.averageRayTreeSize / double(s.nodes) : 0.0;
    // [coherence]
    // END SOLUTION
    // BEGIN STUB
    // // TODO 2: the paper's coherence: the average ray-tree size (rays_ per pixel of the
    // // width_ x height_ image) over the beam tree's size (s.nodes).
    // s.averageRayTreeSize = 0.0;
    // s.coherence = 0.0;
    // END STUB
    return s;
}

}  // namespace rc
