// Tutorial 07, your exercise (open-ended): a better cache for rays that hit nothing. This file is
// yours to edit. Check it with
//   cmake --build build --target tutorial-07      (or: ctest --preset student -R 07)
#include "exercise.h"

namespace tutorial {

// [stub]
double emptyConeAngle([[maybe_unused]] const rc::Vec3& apex, [[maybe_unused]] const rc::Vec3& axis,
                      [[maybe_unused]] const std::vector<rc::Sphere>& spheres) {
    // TODO 1 (basic): the widest empty cone around axis. -1 means "no cone at all".
    return -1.0;
}

namespace {
// TODO 2 and 3: remember what the complete searches found and answer rays from it. Ask
// spheres_ (distance, disc) for what you need to know: the check counts every question.
class MyCache final : public NothingCache {
public:
    explicit MyCache(const Spheres& spheres) : spheres_(spheres) {}
    Known lookup([[maybe_unused]] const rc::Vec3& d) override {
        return {};  // never answers: every ray gets a complete search
    }
    void searched([[maybe_unused]] const rc::Vec3& d, [[maybe_unused]] int object) override {}

private:
    [[maybe_unused]] const Spheres& spheres_;
};
}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const Spheres& spheres) {
    return std::make_unique<MyCache>(spheres);
}
// [stub]

}  // namespace tutorial
