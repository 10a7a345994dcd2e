/* RayCache's one implementation of the math functions its images depend on: musl's
   (Emscripten's copy of musl 1.2.2, see ../COPYRIGHT), compiled into the native and the
   web build alike, so that glibc's and Emscripten's libm cannot make an image's bits
   differ. The names carry a prefix (rename.h): the C library's own stay as they are. */
#ifndef RC_MUSL_MATH_H
#define RC_MUSL_MATH_H
#ifdef __cplusplus
extern "C" {
#endif
double rc_musl_sin(double);
double rc_musl_cos(double);
double rc_musl_tan(double);
double rc_musl_asin(double);
double rc_musl_pow(double, double);
#ifdef __cplusplus
}
#endif
#endif
