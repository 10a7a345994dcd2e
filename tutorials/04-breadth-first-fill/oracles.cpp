// Tutorial 04's oracle, as data (oracle_data.h)
#include "oracles.h"

#include "oracle_data.h"

namespace tutorial {
long oracleRegions(int width, int height, int band, const std::vector<int>& key) {
    return long(TUTORIAL_ORACLE(double, Key("oracleRegions") << width << height << band << key,
                                double(instructor::countRegions(width, height, band, key))));
}
}  // namespace tutorial
