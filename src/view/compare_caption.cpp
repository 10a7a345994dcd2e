#include "view/compare_caption.h"

#include <cstdio>

namespace rc {

std::vector<std::string> compareCaption(const SessionState& left, const SessionState& right) {
    const double a = double(left.session().counters().intersectionTests);
    const double b = double(right.session().counters().intersectionTests);
    char line[160];
    std::vector<std::string> out;
    std::snprintf(line, sizeof line, "tests %.0f = %.2fx the left's %.0f", b, a > 0 ? b / a : 0.0, a);
    out.push_back(line);
    std::snprintf(line, sizeof line, "difference %s%.0f tests", b >= a ? "+" : "", b - a);
    out.push_back(line);
    // Its cache misses, of every path, against the left's
    const double m = double(left.session().counters().misses);
    const double n = double(right.session().counters().misses);
    // With no cache on the left there is nothing to divide by: a ratio would read as 0.00x
    if (m > 0)
        std::snprintf(line, sizeof line, "misses %.0f = %.2fx the left's %.0f", n, n / m, m);
    else
        std::snprintf(line, sizeof line, "misses %.0f (the left has no cache misses)", n);
    out.push_back(line);
    if (left.session().steps() != right.session().steps()) {
        std::snprintf(line, sizeof line, "catching up: step %lld of %lld", (long long)right.session().steps(),
                      (long long)left.session().steps());
        out.push_back(line);
    }
    return out;
}

}  // namespace rc
