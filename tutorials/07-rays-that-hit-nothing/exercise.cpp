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
// TODO 2 and 3: remember what the complete searches found and answer rays from it.
class MyCache final : public NothingCache {
public:
    MyCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) : spheres_(spheres), eye_(eye) {}
    Known lookup([[maybe_unused]] const rc::Vec3& d, [[maybe_unused]] long& tests) override {
        return {};  // never answers: every ray gets a complete search
    }
    void searched([[maybe_unused]] const rc::Vec3& d, [[maybe_unused]] int object) override {}

private:
    std::vector<rc::Sphere> spheres_;
    rc::Vec3 eye_;
};
}  // namespace

std::unique_ptr<NothingCache> makeNothingCache(const std::vector<rc::Sphere>& spheres, const rc::Vec3& eye) {
    return std::make_unique<MyCache>(spheres, eye);
}
// [stub]

}  // namespace tutorial
