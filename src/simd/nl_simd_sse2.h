/* nl_simd_sse2.h - the vector types and primitives every SSE2 kernel shares
 * (noise, cellular, wavelet, math: their *_simd_sse2.c), 2 doubles a vector.
 * Library-internal: included by a kernel file, never installed. SSE2 has
 * no floor instruction (SSE4.1's roundpd): floor goes through the 2^52
 * rounding trick, which gives floor's bits for |x| < 2^52. */
#ifndef NL_SIMD_SSE2_H
#define NL_SIMD_SSE2_H
#include <immintrin.h>

typedef double vd __attribute__((vector_size(16)));
typedef long long vl __attribute__((vector_size(16)));

/* floor for |x| < 2^52: x + copysign(2^52, x) - copysign(2^52, x) rounds x
 * to an integer r (exactly: the sum has no fractional bits left), and
 * r - (r > x) is the floor. A -0 result is the caller's to fix (v_cell). */
static inline vd v_floor(vd x)
{
  vd c = (vd)(((vl)x & (long long)0x8000000000000000ULL) | (vl)((vd){0} + 0x1p52));
  vd r = (x + c) - c;
  return r - (vd)((vl)((vd){0} + 1.0) & (r > x));
}
/* ceil(x) = -floor(-x) (the sign of a zero may differ from ceil's). */
static inline vd v_ceil(vd x) { return -v_floor(-x); }
static inline vd v_min(vd a, vd b) { return (vd)_mm_min_pd((__m128d)a, (__m128d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm_max_pd((__m128d)a, (__m128d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm_sqrt_pd((__m128d)x); }
/* Masks (all bits set or clear per lane): any lane set, every lane set. */
static inline int v_any(vl m) { return _mm_movemask_pd((__m128d)m) != 0; }
static inline int v_all(vl m) { return (m[0] & m[1]) != 0; }

#endif
