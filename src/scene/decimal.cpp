#include "scene/decimal.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <locale.h>

namespace rc {

namespace {
locale_t cLocale() {
    static const locale_t c = newlocale(LC_ALL_MASK, "C", locale_t(nullptr));
    return c;
}
}  // namespace

DecimalStatus parseDecimal(std::string_view token, double& value) {
    if (token.empty()) return DecimalStatus::NotANumber;
    // strtod also takes what std::from_chars's general format does not: space, '+', hex
    const char first = token[0] == '-' && token.size() > 1 ? token[1] : token[0];
    if (first == '+' || first == '-' || first == ' ' || first == '\t') return DecimalStatus::NotANumber;
    if (token.find_first_of("xX") != std::string_view::npos) return DecimalStatus::NotANumber;
    const std::string text(token);
    char* end = nullptr;
    errno = 0;
    const double v = strtod_l(text.c_str(), &end, cLocale());
    if (end != text.c_str() + text.size()) return DecimalStatus::NotANumber;
    // Beyond double's range, or so small it rounds to 0; a subnormal number is a number
    if (errno == ERANGE && (std::isinf(v) || v == 0.0)) return DecimalStatus::OutOfRange;
    value = v;
    return DecimalStatus::Ok;
}

std::size_t formatDecimal(double v, int digits, char* out, std::size_t size) {
    // printf has no locale argument: switch this thread to "C" for the call
    const locale_t previous = uselocale(cLocale());
    const int n = std::snprintf(out, size, "%.*g", digits, v);
    uselocale(previous);
    return n < 0 ? 0 : std::size_t(n);
}

}  // namespace rc
