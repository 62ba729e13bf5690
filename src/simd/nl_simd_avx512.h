/* nl_simd_avx512.h - the vector types and primitives every AVX-512 kernel
 * shares (noise, cellular, wavelet, math: their *_simd_avx512.c), 8 doubles a
 * vector, and the target pragma (F, DQ, BW, VL, VBMI): a kernel file
 * includes it first, so the whole file compiles for the level, never with
 * -march. Library-internal, never installed. */
#ifndef NL_SIMD_AVX512_H
#define NL_SIMD_AVX512_H
/* The level's target for the rest of the including file (clang's push is
 * popped at that file's end). */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2"))), apply_to = function)
#else
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2")
#endif
#include <immintrin.h>

typedef double vd __attribute__((vector_size(64)));
typedef long long vl __attribute__((vector_size(64)));

static inline vd v_floor(vd x)
{
  return (vd)_mm512_roundscale_pd((__m512d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
static inline vd v_ceil(vd x)
{
  return (vd)_mm512_roundscale_pd((__m512d)x, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC);
}
static inline vd v_min(vd a, vd b) { return (vd)_mm512_min_pd((__m512d)a, (__m512d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm512_max_pd((__m512d)a, (__m512d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm512_sqrt_pd((__m512d)x); }
/* Masks (all bits set or clear per lane): any lane set, every lane set. */
static inline int v_any(vl m) { return _mm512_movepi64_mask((__m512i)m) != 0; }
static inline int v_all(vl m) { return _mm512_movepi64_mask((__m512i)m) == 0xff; }

#endif
