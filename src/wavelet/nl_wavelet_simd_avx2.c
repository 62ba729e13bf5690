/* nl_wavelet_simd_avx2.c - nl_wavelet_simd_body.h for AVX2, 4 doubles a
 * vector. Compiled with a target pragma, never -march: called only when
 * the library's level (nl_simd_get) says the CPU runs it. No FMA. */
#include "simd/nl_simd_avx2.h"   /* vd, vl, v_ceil */
#include "wavelet/nl_wavelet_simd.h"

#define NL_SIMD_W 4
typedef int vi __attribute__((vector_size(16)));

#include "simd/nl_simd_lanes.h"   /* v_gd */
#include "simd/nl_simd_vec.h"     /* ld, st, SPLAT */
#include "wavelet/nl_wavelet_simd_body.h"

const nl_wavelet_simd_row_fn nl_wavelet_simd_avx2 = bspline_lanes;

#if defined(__clang__)
#pragma clang attribute pop
#endif
