// Tutorial 02's oracles, as data (oracle_data.h)
#include "oracles.h"

#include "oracle_data.h"

namespace tutorial {
double segmentGap(const rc::Vec3& p, const rc::Vec3& a, const rc::Vec3& b) {
    return TUTORIAL_ORACLE(double, Key("segmentGap") << p << a << b, instructor::segmentGap(p, a, b));
}
bool capsuleContains(const rc::Vec3& a, const rc::Vec3& b, double radius, const rc::Vec3& p, const rc::Vec3& q) {
    return TUTORIAL_ORACLE(double, Key("capsuleContains") << a << b << radius << p << q,
                           instructor::capsuleContains(a, b, radius, p, q) ? 1.0 : 0.0) != 0.0;
}
double sphereGap(const std::vector<rc::Sphere>& spheres, int hit, const rc::Vec3& a, const rc::Vec3& b) {
    return TUTORIAL_ORACLE(double, Key("sphereGap") << spheres << hit << a << b,
                           instructor::sphereGap(spheres, hit, a, b));
}
}  // namespace tutorial
