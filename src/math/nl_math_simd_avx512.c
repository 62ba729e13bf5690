/* nl_math_simd_avx512.c - nl_math_simd_body.h for AVX-512, 8 doubles a vector.
 * Compiled with a target pragma, never -march: called only when the
 * dispatcher (nl_math_simd.c) has seen the CPU support it. */
#include "simd/nl_simd_avx512.h"   /* vd, vl, v_all */

#define NL_SIMD_W 8
#define NL_SIMD_SINPI_N nl_math__sinpi_n_avx512

#include "math/nl_math_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
