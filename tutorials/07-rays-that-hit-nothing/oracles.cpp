// Tutorial 07's oracles, as data (oracle_data.h)
#include "oracles.h"

#include <stdexcept>
#include <string>

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
std::vector<int> eyeHits(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height) {
    const std::vector<double> v = TUTORIAL_ORACLE(
        std::vector<double>,
        Key("eyeHits") << spheres << camera.from << camera.at << camera.up << camera.angle << width << height,
        instructor::eyeHits(spheres, camera, width, height));
    if (v.size() != std::size_t(width) * std::size_t(height))
        throw std::logic_error("oracle data: eyeHits holds " + std::to_string(v.size()) + " pixels, not " +
                               std::to_string(width * height));
    return std::vector<int>(v.begin(), v.end());
}
CylinderRow cylinderRow(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height) {
    // {cost, emptyCost, searchesPerBeam, testsPerAnswer, searches, tests, afterEmptyAnswered, afterEmpty}
    const std::vector<double> v = TUTORIAL_ORACLE(
        std::vector<double>,
        Key("cylinderRow") << spheres << camera.from << camera.at << camera.up << camera.angle << width << height,
        instructor::cylinderRow(spheres, camera, width, height));
    return {v.at(0), v.at(1), v.at(2), v.at(3), long(v.at(4)), long(v.at(5)), long(v.at(6)), long(v.at(7))};
}
long emptyBeams(int width, int height, const std::vector<int>& truth) {
    return long(TUTORIAL_ORACLE(double, Key("emptyBeams") << width << height << truth,
                                double(instructor::emptyBeams(width, height, truth))));
}
}  // namespace tutorial
