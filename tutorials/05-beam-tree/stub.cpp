// Tutorial 05: the exercise as shipped, a READ-ONLY copy of exercise.cpp. Do not edit it:
// your work goes in exercise.cpp. The docs quote this file and CI checks that it still fails.
#include "exercise.h"

namespace tutorial {

// [stub]
BeamStats beamTree([[maybe_unused]] int width, [[maybe_unused]] int height,
                   [[maybe_unused]] const std::vector<PathImage>& paths) {
    // TODO: count the beams of every path and compute the coherence.
    return BeamStats{};
}
// [stub]

}  // namespace tutorial
