/* nl_simd_avx2.h - the vector types and primitives every AVX2 kernel shares
 * (noise, cellular, wavelet, math, cheng: their *_simd_avx2.c), 4 doubles a vector,
 * and the target pragma ("avx2"): a kernel file includes it first, so the
 * whole file compiles for the level, never with -march. Library-internal,
 * never installed. */
#ifndef NL_SIMD_AVX2_H
#define NL_SIMD_AVX2_H
/* The level's target for the rest of the including file (clang's push is
 * popped at that file's end). */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC target("avx2")
#endif
#include <immintrin.h>

typedef double vd __attribute__((vector_size(32)));
typedef long long vl __attribute__((vector_size(32)));

static inline vd v_floor(vd x) { return (vd)_mm256_floor_pd((__m256d)x); }
static inline vd v_ceil(vd x) { return (vd)_mm256_ceil_pd((__m256d)x); }
static inline vd v_min(vd a, vd b) { return (vd)_mm256_min_pd((__m256d)a, (__m256d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm256_max_pd((__m256d)a, (__m256d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm256_sqrt_pd((__m256d)x); }
/* Masks (all bits set or clear per lane): any lane set, every lane set. */
static inline int v_any(vl m) { return _mm256_movemask_pd((__m256d)m) != 0; }
static inline int v_all(vl m) { return _mm256_movemask_pd((__m256d)m) == 15; }

#endif
