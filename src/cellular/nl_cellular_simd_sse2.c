/* nl_cellular_simd_sse2.c - the cellular row kernel of nl_cellular_simd_body.h
 * for sse2, 2 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the library's level (nl_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include "simd/nl_simd_sse2.h"   /* vd, vl, v_floor, v_min, v_max, v_sqrt, v_any */

#define NL_CELL_W 2
#define NL_CELL_ROW nl_cellular_row_sse2

#include "cellular/nl_cellular_simd_body.h"
