/* nl_noise_simd_sse2.c - the kernels of nl_noise_simd_body.h for the x86-64
 * baseline (SSE2), 2 doubles a vector. SSE2 has neither a floor instruction
 * (SSE4.1's roundpd) nor gathers: floor goes through the 2^52 rounding
 * trick, lookups lane by lane. */
#include "noise/nl_noise_simd.h"
#include "simd/nl_simd_sse2.h"   /* vd, vl, v_floor, v_ceil, v_all */

#define NL_SIMD_W 2
#define NL_SIMD_TABLE nl_noise_simd_sse2
typedef int vi __attribute__((vector_size(8)));
typedef unsigned vu __attribute__((vector_size(8)));

static inline vd v_gd(const double *b, vi i) { return (vd){b[i[0]], b[i[1]]}; }
static inline vi v_gi(const int *b, vi i) { return (vi){b[i[0]], b[i[1]]}; }

#include "noise/nl_noise_simd_body.h"

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples_lanes, columns3, points2_fold, points3_lanes,
                                           points3_sum_lanes, points3_bounded_lanes,
                                           refused_lanes};
