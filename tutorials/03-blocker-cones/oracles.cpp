// Tutorial 03's oracles, as data (oracle_data.h)
#include "oracles.h"

#include <vector>

#include "oracle_data.h"

namespace tutorial {
double hullGap(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b) {
    return TUTORIAL_ORACLE(double, Key("hullGap") << p << a << b, double(instructor::hullGap(p, a, b)));
}
std::string hullSlice(const rc::Sphere& a, const rc::Sphere& b, int w, int h, double x0, double y0, double scale) {
    // The slice, 52 pixels to a number (each a bit), at full precision as a double holds them
    const std::vector<double> words =
        TUTORIAL_ORACLE(std::vector<double>, Key("hullSlice") << a << b << w << h << x0 << y0 << scale,
                        instructor::hullSlice(a, b, w, h, x0, y0, scale));
    std::string out(std::size_t(w) * h, '0');
    for (std::size_t i = 0; i < out.size() && i / 52 < words.size(); ++i)
        if ((static_cast<unsigned long long>(words[i / 52]) >> (i % 52)) & 1ull) out[i] = '1';
    return out;
}
std::vector<int> blockerList(const rc::Sphere& a, const rc::Sphere& b, const std::vector<rc::Sphere>& spheres, int skip) {
    const std::vector<double> ids = TUTORIAL_ORACLE(std::vector<double>, Key("blockerList") << a << b << spheres << skip,
                                                    instructor::blockerList(a, b, spheres, skip));
    return std::vector<int>(ids.begin(), ids.end());
}
}  // namespace tutorial
