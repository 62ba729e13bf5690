/* nl_math_simd_avx2.c - nl_math_simd_body.h for AVX2, 4 doubles a vector.
 * Compiled with a target pragma, never -march: called only when the
 * dispatcher (nl_math_simd.c) has seen the CPU support it. */
#include "simd/nl_simd_avx2.h"   /* vd, vl, v_all */

#define NL_SIMD_W 4
#define NL_SIMD_SINPI_N nl_math__sinpi_n_avx2

#include "math/nl_math_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
