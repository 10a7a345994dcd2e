// Tutorial 01's oracle, as data (oracle_data.h)
#include "oracles.h"

#include "geometry/intersection.h"
#include "oracle_data.h"

namespace tutorial {
rc::Answer oracleNearest(const std::vector<rc::Sphere>& spheres, const rc::Query& q, bool& ambiguous, long& tests) {
    // {object, t, ambiguous, tests}
    const std::vector<double> v = TUTORIAL_ORACLE(
        std::vector<double>,
        Key("oracleNearest") << spheres << q.ray << q.origin.object << int(q.origin.inside) << q.tmax,
        instructor::nearest(spheres, q));
    ambiguous = v.at(2) != 0.0;
    tests = long(v.at(3));
    return {int(v.at(0)), v.at(1)};
}
}  // namespace tutorial
