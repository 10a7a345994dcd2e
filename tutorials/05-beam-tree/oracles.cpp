// Tutorial 05's oracle, as data (oracle_data.h)
#include "oracles.h"

#include "oracle_data.h"

namespace tutorial {
namespace {
Key& operator<<(Key& key, const PathImage& path) {
    key << int(path.size());
    for (const PixelRay& r : path) key << int(r.present) << r.origin << int(r.inside) << r.hit;
    return key;
}
}  // namespace

BeamStats oracleBeams(int width, int height, const std::vector<PathImage>& paths) {
    Key key("oracleBeams");
    key << width << height << int(paths.size());
    for (const PathImage& path : paths) key << path;
    const std::vector<double> v =
        TUTORIAL_ORACLE(std::vector<double>, key, instructor::beams(width, height, paths));
    return {std::int64_t(v.at(0)), v.at(1)};
}

std::vector<int> oracleLabels(int width, int height, const PathImage& path) {
    Key key("oracleLabels");
    key << width << height << path;
    const std::vector<double> v =
        TUTORIAL_ORACLE(std::vector<double>, key, instructor::labels(width, height, path));
    return std::vector<int>(v.begin(), v.end());
}
}  // namespace tutorial
