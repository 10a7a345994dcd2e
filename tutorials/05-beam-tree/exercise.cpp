// Tutorial 05, your exercise: the beam tree. Build and run the check with
//   cmake --build build --target tutorial_05_check_stub && build/tutorials/tutorial_05_check_stub
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
