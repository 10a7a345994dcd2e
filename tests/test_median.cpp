// The one median of the code base (the times of table1, bench and coherence; the stability study's hit-distance errors).
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/median.h"

using namespace rc;

TEST_CASE("median: the middle value, the mean of the middle two, NaN for none", "[median]") {
    CHECK(median({5.0}) == 5.0);
    CHECK(median({3.0, 1.0, 2.0}) == 2.0);            // unsorted input
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5);       // (2 + 3) / 2
    CHECK(median({1.0, 100.0, 2.0}) == 2.0);          // an outlier does not pull it
    CHECK(median({7.0, 7.0, 1.0, 9.0, 7.0}) == 7.0);  // repeated values
    CHECK(std::isnan(median({})));
}
