/* nl_cellular_simd_avx512.c - the cellular row kernel of nl_cellular_simd_body.h
 * for avx512, 8 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the noise module's level (nl_noise_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2"))), apply_to = function)
#else
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2")
#endif
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include <immintrin.h>

#define NL_CELL_W 8
#define NL_CELL_ROW nl_cellular_row_avx512
typedef double vd __attribute__((vector_size(64)));
typedef long long vl __attribute__((vector_size(64)));

static inline vd v_floor(vd x)
{
  return (vd)_mm512_roundscale_pd((__m512d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
static inline vd v_min(vd a, vd b) { return (vd)_mm512_min_pd((__m512d)a, (__m512d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm512_max_pd((__m512d)a, (__m512d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm512_sqrt_pd((__m512d)x); }
static inline int v_any(vl m) { return _mm512_movepi64_mask((__m512i)m) != 0; }

#include "cellular/nl_cellular_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
