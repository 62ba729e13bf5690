/* nl_cellular_simd_avx512.c - the cellular row kernel of nl_cellular_simd_body.h
 * for avx512, 8 doubles a vector. Compiled with a target pragma, never -march:
 * called only when the library's level (nl_simd_get) says the CPU
 * runs it. No FMA (-ffp-contract=off, no fused intrinsics): see
 * nl_cellular_simd.h. */
#if defined(__clang__)   /* clang has no GCC target pragma; popped at the end */
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2"))), apply_to = function)
#else
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2")
#endif
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include "simd/nl_simd_avx512.h"   /* vd, vl, v_floor, v_min, v_max, v_sqrt, v_any */

#define NL_CELL_W 8
#define NL_CELL_ROW nl_cellular_row_avx512

#include "cellular/nl_cellular_simd_body.h"

#if defined(__clang__)
#pragma clang attribute pop
#endif
