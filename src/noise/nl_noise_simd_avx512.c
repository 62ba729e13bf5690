/* nl_noise_simd_avx512.c - the kernels of nl_noise_simd_body.h for AVX-512
 * (F, DQ, BW, VL: x86-64-v4), 8 doubles a vector. Compiled with a target
 * pragma, never -march: called only when the dispatcher has seen the CPU
 * (and the OS) support it. No FMA: see nl_noise_simd.h. */
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl,avx2")
#include "noise/nl_noise_simd.h"
#include <immintrin.h>

#define NL_SIMD_W 8
#define NL_SIMD_TABLE nl_noise_simd_avx512
typedef double vd __attribute__((vector_size(64)));
typedef long long vl __attribute__((vector_size(64)));
typedef int vi __attribute__((vector_size(32)));
typedef unsigned vu __attribute__((vector_size(32)));

static inline vd v_floor(vd x)
{
  return (vd)_mm512_roundscale_pd((__m512d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
static inline vd v_gd(const double *b, vi i) { return (vd)_mm512_i32gather_pd((__m256i)i, b, 8); }
static inline vi v_gi(const int *b, vi i) { return (vi)_mm256_i32gather_epi32(b, (__m256i)i, 4); }
static inline int v_all(vl m) { return _mm512_movepi64_mask((__m512i)m) == 0xff; }

#include "noise/nl_noise_simd_body.h"
