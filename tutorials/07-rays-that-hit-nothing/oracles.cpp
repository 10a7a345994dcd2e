// Tutorial 07's oracles, as data (oracle_data.h)
#include "oracles.h"

#include "oracle_data.h"

namespace tutorial {
double oracleConeAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres) {
    return TUTORIAL_ORACLE(double, Key("oracleConeAngle") << apex << axis << spheres,
                           instructor::coneAngle(apex, axis, spheres));
}
OneCone oneCone(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height) {
    // {searches, emptySearches, cost}
    const std::vector<double> v = TUTORIAL_ORACLE(
        std::vector<double>,
        Key("oneCone") << spheres << camera.from << camera.at << camera.up << camera.angle << width << height,
        instructor::oneCone(spheres, camera, width, height));
    return {long(v.at(0)), long(v.at(1)), v.at(2)};
}
long emptyBeams(int width, int height, const std::vector<int>& truth) {
    return long(TUTORIAL_ORACLE(double, Key("emptyBeams") << width << height << truth,
                                double(instructor::emptyBeams(width, height, truth))));
}
}  // namespace tutorial
