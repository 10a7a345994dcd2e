#include "view/compare_caption.h"

#include <cstdio>

namespace rc {

namespace {
/// "WHAT N = R.RRx the left's M", or, when the left has none to divide by, "WHAT N (NONE)":
/// a ratio of 0.00x would read as a measurement
std::string againstLeft(const char* what, double right, double left, const char* none) {
    char line[160];
    if (left > 0)
        std::snprintf(line, sizeof line, "%s %.0f = %.2fx the left's %.0f", what, right, right / left, left);
    else
        std::snprintf(line, sizeof line, "%s %.0f (%s)", what, right, none);
    return line;
}
}  // namespace

std::vector<std::string> compareCaption(const SessionState& left, const SessionState& right) {
    const double a = double(left.session().counters().intersectionTests);
    const double b = double(right.session().counters().intersectionTests);
    char line[160];
    std::vector<std::string> out;
    out.push_back(againstLeft("tests", b, a, "the left made none"));
    std::snprintf(line, sizeof line, "difference %s%.0f tests", b >= a ? "+" : "", b - a);
    out.push_back(line);
    // Its cache misses, of every path, against the left's (none when the left has no cache)
    const double m = double(left.session().counters().misses);
    const double n = double(right.session().counters().misses);
    out.push_back(againstLeft("misses", n, m, "the left has no cache misses"));
    if (left.session().steps() != right.session().steps()) {
        std::snprintf(line, sizeof line, "catching up: step %lld of %lld", (long long)right.session().steps(),
                      (long long)left.session().steps());
        out.push_back(line);
    }
    return out;
}

}  // namespace rc
