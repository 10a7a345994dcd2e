/* RayCache: the part of <math.h> that this folder's musl sources use, so that they compile
   alike against glibc and against Emscripten's libc. What they call from the C library
   (floor, scalbn, fabs) is exact, so every libc gives the same bits. */
#ifndef RAYCACHE_MUSL_MATH_H
#define RAYCACHE_MUSL_MATH_H
#include "../public/rc_musl_math.h"
typedef double double_t;
typedef float float_t;
#define INFINITY __builtin_inff()
#define NAN __builtin_nanf("")
#define isnan(x) __builtin_isnan(x)
#define isinf(x) __builtin_isinf(x)
#define signbit(x) __builtin_signbit(x)
double floor(double);
double scalbn(double, int);
double fabs(double);
double sqrt(double);
#endif
