/* nl_cellular_simd_avx2.c - the cellular row kernel of nl_cellular_simd_body.h
 * for avx2, 4 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the noise module's level (nl_noise_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC target("avx2")
#endif
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include <immintrin.h>

#define NL_CELL_W 4
#define NL_CELL_ROW nl_cellular_row_avx2
typedef double vd __attribute__((vector_size(32)));
typedef long long vl __attribute__((vector_size(32)));

static inline vd v_floor(vd x) { return (vd)_mm256_floor_pd((__m256d)x); }
static inline vd v_min(vd a, vd b) { return (vd)_mm256_min_pd((__m256d)a, (__m256d)b); }
static inline vd v_max(vd a, vd b) { return (vd)_mm256_max_pd((__m256d)a, (__m256d)b); }
static inline vd v_sqrt(vd x) { return (vd)_mm256_sqrt_pd((__m256d)x); }
static inline int v_any(vl m) { return _mm256_movemask_pd((__m256d)m) != 0; }

#include "cellular/nl_cellular_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
