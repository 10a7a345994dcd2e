// Tutorial 06's oracles, as data (oracle_data.h)
#include "oracles.h"

#include "oracle_data.h"

namespace tutorial {
rc::SphereRoots oracleSphereRoots(const rc::Ray& ray, const rc::Sphere& s) {
    const std::vector<double> r =
        TUTORIAL_ORACLE(std::vector<double>, Key("oracleSphereRoots") << ray << s, instructor::roots(ray, s));
    if (r.size() != 3 || r[0] == 0.0) return {};
    return {true, r[1], r[2]};
}
int oracleFirstHit(const rc::Ray& ray, const std::vector<rc::Sphere>& spheres) {
    return int(TUTORIAL_ORACLE(double, Key("oracleFirstHit") << ray << spheres, instructor::firstHit(ray, spheres)));
}
}  // namespace tutorial
