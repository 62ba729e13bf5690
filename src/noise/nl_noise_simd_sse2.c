/* nl_noise_simd_sse2.c - the kernels of nl_noise_simd_body.h for the x86-64
 * baseline (SSE2), 2 doubles a vector. SSE2 has neither a floor instruction
 * (SSE4.1's roundpd) nor gathers: floor goes through the 2^52 rounding
 * trick, lookups lane by lane. */
#include "noise/nl_noise_simd.h"

#define NL_SIMD_W 2
#define NL_SIMD_TABLE nl_noise_simd_sse2
typedef double vd __attribute__((vector_size(16)));
typedef long long vl __attribute__((vector_size(16)));
typedef int vi __attribute__((vector_size(8)));
typedef unsigned vu __attribute__((vector_size(8)));

/* floor for |x| < 2^52: x + copysign(2^52, x) - copysign(2^52, x) rounds x
 * to an integer r (exactly: the sum has no fractional bits left), and
 * r - (r > x) is the floor. A -0 result is fixed by the caller (v_cell). */
static inline vd v_floor(vd x)
{
  vd c = (vd)(((vl)x & (long long)0x8000000000000000ULL) | (vl)((vd){0} + 0x1p52));
  vd r = (x + c) - c;
  return r - (vd)((vl)((vd){0} + 1.0) & (r > x));
}
/* ceil(x) = -floor(-x) (the sign of a zero may differ from ceil's). */
static inline vd v_ceil(vd x) { return -v_floor(-x); }
static inline vd v_gd(const double *b, vi i) { return (vd){b[i[0]], b[i[1]]}; }
static inline vi v_gi(const int *b, vi i) { return (vi){b[i[0]], b[i[1]]}; }
static inline int v_all(vl m) { return (m[0] & m[1]) != 0; }

#include "noise/nl_noise_simd_body.h"

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples_lanes, columns3, points2, points3_lanes, bspline_lanes,
                                           points3_sum_lanes, points3_bounded_lanes};
