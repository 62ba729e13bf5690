/* nl_cellular_simd_sse2.c - the cellular row kernel of nl_cellular_simd_body.h
 * for sse2, 2 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the noise module's level (nl_noise_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include <immintrin.h>

#define NL_CELL_W 2
#define NL_CELL_ROW nl_cellular_row_sse2
typedef double vd __attribute__((vector_size(16)));
typedef long long vl __attribute__((vector_size(16)));

static inline vd v_floor(vd x)
{
  vd c = (vd)(((vl)x & (long long)0x8000000000000000ULL) | (vl)((vd){0} + 0x1p52));
  vd r = (x + c) - c;
  return r - (vd)((vl)((vd){0} + 1.0) & (r > x));
}
static inline vd v_min(vd a, vd b) { return (vd)_mm_min_pd((__m128d)a, (__m128d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm_max_pd((__m128d)a, (__m128d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm_sqrt_pd((__m128d)x); }
static inline int v_any(vl m) { return _mm_movemask_pd((__m128d)m) != 0; }

#include "cellular/nl_cellular_simd_body.h"
