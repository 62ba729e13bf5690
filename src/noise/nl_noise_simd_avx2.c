/* nl_noise_simd_avx2.c - the kernels of nl_noise_simd_body.h for AVX2, 4
 * doubles a vector. Compiled with a target pragma, never -march: called only
 * when the dispatcher has seen the CPU support it. No FMA: see
 * nl_noise_simd.h. */
#include "simd/nl_simd_avx2.h"   /* vd, vl, v_floor, v_ceil, v_all */
#include "noise/nl_noise_simd.h"
#include <string.h>

#define NL_SIMD_W 4
#define NL_SIMD_TABLE nl_noise_simd_avx2
typedef int vi __attribute__((vector_size(16)));
typedef unsigned vu __attribute__((vector_size(16)));

/* Lookups lane by lane: on the machines measured (AMD Zen 4) a gather
 * instruction costs more than its loads one by one. */
#include "simd/nl_simd_lanes.h"

#include "noise/nl_noise_simd_body.h"

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples_lanes, columns3, points2_fold, points3_lanes,
                                           points3_sum_lanes, points3_bounded_lanes,
                                           refused_lanes};

#if defined(__clang__)
#pragma clang attribute pop
#endif
