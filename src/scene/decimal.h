#pragma once
/// \file
/// \brief Decimal numbers read and written the same way in every build and every locale:
/// C's conversions in the "C" locale, correctly rounded by glibc and by Emscripten's musl
/// alike (libc++ 14, the web edition's, has no floating-point std::from_chars).
#include <cstddef>
#include <string_view>

namespace rc {

/// Why a token is not a number.
enum class DecimalStatus { Ok, NotANumber, OutOfRange };

/// Reads a whole token as a decimal floating-point number, correctly rounded: digits, a
/// point, an exponent, or inf/nan. A leading '-', no leading '+' or space, no hexadecimal.
/// "1.0abc" is not a number; a number beyond double's range, or one that rounds to 0
/// (1e-400, not 0.0), is OutOfRange; a subnormal one (4.9e-324) is read.
DecimalStatus parseDecimal(std::string_view token, double& value);

/// `v` as printf's `%.{digits}g` writes it in the "C" locale, into `out` (of `size` bytes).
/// Returns the characters written.
std::size_t formatDecimal(double v, int digits, char* out, std::size_t size);

}  // namespace rc
