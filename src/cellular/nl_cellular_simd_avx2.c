/* nl_cellular_simd_avx2.c - the cellular row kernel of nl_cellular_simd_body.h
 * for avx2, 4 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the library's level (nl_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#include "simd/nl_simd_avx2.h"   /* vd, vl, v_floor, v_min, v_max, v_sqrt, v_any */
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"

#define NL_CELL_W 4
#define NL_CELL_ROW nl_cellular_row_avx2

#include "cellular/nl_cellular_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
