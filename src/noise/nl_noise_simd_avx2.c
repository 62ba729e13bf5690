/* nl_noise_simd_avx2.c - the kernels of nl_noise_simd_body.h for AVX2, 4
 * doubles a vector. Compiled with a target pragma, never -march: called only
 * when the dispatcher has seen the CPU support it. No FMA: see
 * nl_noise_simd.h. */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC target("avx2")
#endif
#include "noise/nl_noise_simd.h"
#include <immintrin.h>
#include <string.h>

#define NL_SIMD_W 4
#define NL_SIMD_TABLE nl_noise_simd_avx2
typedef double vd __attribute__((vector_size(32)));
typedef long long vl __attribute__((vector_size(32)));
typedef int vi __attribute__((vector_size(16)));
typedef unsigned vu __attribute__((vector_size(16)));

static inline vd v_floor(vd x) { return (vd)_mm256_floor_pd((__m256d)x); }
static inline vd v_ceil(vd x) { return (vd)_mm256_ceil_pd((__m256d)x); }
/* Lookups lane by lane: on the machines measured (AMD Zen 5) a gather
 * instruction costs more than its loads one by one. */
#include "noise/nl_noise_simd_lanes.h"
static inline int v_all(vl m) { return _mm256_movemask_pd((__m256d)m) == 15; }

#include "noise/nl_noise_simd_body.h"

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples_lanes, columns3, points2, points3_lanes, bspline_lanes,
                                           points3_sum_lanes, points3_bounded_lanes};

#if defined(__clang__)
#pragma clang attribute pop
#endif
