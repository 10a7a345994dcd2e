/* RayCache: compiled before each file of this folder (-include): musl's names, prefixed */
#define sin rc_musl_sin
#define cos rc_musl_cos
#define tan rc_musl_tan
#define asin rc_musl_asin
#define pow rc_musl_pow
#define __sin rc_musl___sin
#define __cos rc_musl___cos
#define __tan rc_musl___tan
#define __rem_pio2 rc_musl___rem_pio2
#define __rem_pio2_large rc_musl___rem_pio2_large
#define __math_divzero rc_musl___math_divzero
#define __math_invalid rc_musl___math_invalid
#define __math_oflow rc_musl___math_oflow
#define __math_uflow rc_musl___math_uflow
#define __math_xflow rc_musl___math_xflow
#define __exp_data rc_musl___exp_data
#define __pow_log_data rc_musl___pow_log_data
#define hidden
