#pragma once
/// \file
/// \brief The math functions an image depends on, the same bits in every build: glibc's and
/// Emscripten's libm differ in the last bit of some results of sin, cos, tan, asin and pow,
/// so the native and the web edition both call musl's (third_party/musl_math). The
/// sphereflake alone keeps the C library's: SPD's balls files were printed with glibc's.
/// sqrt is exact everywhere and stays std::sqrt.
#include <rc_musl_math.h>

namespace rc::pm {

inline double sin(double x) { return rc_musl_sin(x); }
inline double cos(double x) { return rc_musl_cos(x); }
inline double tan(double x) { return rc_musl_tan(x); }
inline double asin(double x) { return rc_musl_asin(x); }
inline double pow(double x, double y) { return rc_musl_pow(x, y); }

}  // namespace rc::pm
