/* nl_simd.h - the vector level the library's kernels run on, chosen once
 * per process: one dispatch for noise, cellular, wavelet,
 * math (sinpi of an array) and the annealer's pool moves (cheng).
 *
 * The levels are SSE2 (the x86-64 baseline), AVX2 and AVX-512 (F, DQ, BW,
 * VL, VBMI), or scalar code. The best the CPU and OS support is found with
 * __builtin_cpu_supports (which checks the XSAVE state too); the build
 * never uses -march, each kernel file has its own target pragma. Every
 * level gives the scalar code's bits (the kernels repeat its IEEE
 * operations lane by lane, no FMA), so the level changes speed only.
 *
 *   NL_NOISE_SIMD=scalar|sse2|avx2|avx512|auto   in the environment, read at
 *                                                the first nl_simd_get()
 *   nl_simd_set(NL_SIMD_SSE2);                   or from a program (tests and
 *                                                benchmarks compare levels)
 *
 * A level the CPU lacks falls back to the best it has, with a warning on
 * stderr. The vector types and primitives of each level are in
 * nl_simd_sse2.h, nl_simd_avx2.h, nl_simd_avx512.h and nl_simd_lanes.h:
 * library-internal headers, included by kernel files after their target
 * pragma, never installed.
 */
#ifndef NL_SIMD_H
#define NL_SIMD_H

/* 1 where the SSE2, AVX2 and AVX-512 kernels are built (x86 and x86-64,
 * meson.build's cpu_family); elsewhere (aarch64) every kernel is the scalar
 * code and nl_simd_supported says so. */
#if defined(__x86_64__) || defined(__i386__)
#define NL_SIMD_X86 1
#else
#define NL_SIMD_X86 0
#endif

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  NL_SIMD_SCALAR = 0, NL_SIMD_SSE2 = 1, NL_SIMD_AVX2 = 2, NL_SIMD_AVX512 = 3
} nl_simd_level;

int nl_simd_get(void);               /* the level in use */
int nl_simd_best(void);              /* the best this CPU runs */
int nl_simd_supported(int level);    /* 1 if this CPU runs it */
/* NL_OK, or NL_EINVAL for a level that does not exist or that this CPU cannot
 * run (nl_simd_supported tells which); the level in use is then unchanged. */
nl_status nl_simd_set(int level);
const char *nl_simd_name(int level);          /* "scalar", ..., "avx512"; "unknown" */
int nl_simd_from_name(const char *name);      /* -1 if none */

#ifdef __cplusplus
}
#endif

#endif
