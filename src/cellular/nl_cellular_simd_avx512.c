/* nl_cellular_simd_avx512.c - the cellular row kernel of nl_cellular_simd_body.h
 * for avx512, 8 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the library's level (nl_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#include "simd/nl_simd_avx512.h"   /* vd, vl, v_floor, v_min, v_max, v_sqrt, v_any */
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"

#define NL_CELL_W 8
#define NL_CELL_ROW nl_cellular_row_avx512

#include "cellular/nl_cellular_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
