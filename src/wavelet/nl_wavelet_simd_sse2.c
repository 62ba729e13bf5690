/* nl_wavelet_simd_sse2.c - nl_wavelet_simd_body.h for the x86-64 baseline
 * (SSE2), 2 doubles a vector; lookups lane by lane. */
#include "wavelet/nl_wavelet_simd.h"
#include "simd/nl_simd_sse2.h"   /* vd, vl, v_ceil */

#define NL_SIMD_W 2
typedef int vi __attribute__((vector_size(8)));

#include "simd/nl_simd_lanes.h"   /* v_gd */
#include "simd/nl_simd_vec.h"     /* ld, st, SPLAT */
#include "wavelet/nl_wavelet_simd_body.h"

const nl_wavelet_simd_row_fn nl_wavelet_simd_sse2 = bspline_lanes;
