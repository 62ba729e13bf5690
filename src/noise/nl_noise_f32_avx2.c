/* nl_noise_f32_avx2.c - the float32 kernels (nl_noise_f32_body.h) for AVX2
 * with FMA, 8 floats a vector. Compiled with a target pragma, never
 * -march: called only when the dispatcher has seen the CPU support it.
 *
 * AVX2 has no byte permute across a register, so Perlin's table is read
 * by 32-bit gathers at byte offsets: the gather at X brings P[X] and
 * P[X + 1] in one lane (the table is doubled, so X + 3 < 512), seven
 * gathers hash 8 points. His 16 gradients are two registers per
 * component, read by vpermps and chosen by bit 3 of the hash. */
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,fma"))), apply_to = function)
#else
#pragma GCC target("avx2,fma")
#endif
#include <immintrin.h>

#include "noise/nl_noise_f32_impl.h"

#define W 8
typedef float vf __attribute__((vector_size(32)));
typedef int vi __attribute__((vector_size(32)));

#define NLF_FMA(a, b, c) ((vf)_mm256_fmadd_ps((__m256)(a), (__m256)(b), (__m256)(c)))
#define NLF_C(k) ((vf)_mm256_set1_ps(k))

static inline vf v_floor(vf x) { return (vf)_mm256_floor_ps((__m256)x); }
static inline vi v_cvtt(vf x) { return (vi)_mm256_cvttps_epi32((__m256)x); }
static inline vf v_i2f(vi x) { return (vf)_mm256_cvtepi32_ps((__m256i)x); }
static inline vf v_abs(vf x)
{
  return (vf)_mm256_and_ps((__m256)x, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff)));
}
static inline vi vi_c(int k) { return (vi)_mm256_set1_epi32(k); }
static inline vf v_load(const float *p) { return (vf)_mm256_loadu_ps(p); }
static inline void v_store(float *p, vf v) { _mm256_storeu_ps(p, (__m256)v); }

typedef struct { const unsigned char *P; __m256 g[3][2]; } p3ctx;
static inline p3ctx p3ctx_make(const nl_noise_perm3 *p)
{
  p3ctx c;
  c.P = p->p;
  for (int k = 0; k < 3; k++) {
    c.g[k][0] = _mm256_loadu_ps(nl_noise_f32_g3[k]);
    c.g[k][1] = _mm256_loadu_ps(nl_noise_f32_g3[k] + 8);
  }
  return c;
}
/* bytes P[i], P[i + 1], P[i + 2], P[i + 3] of i < 256 */
static inline __m256i gat(const p3ctx *c, __m256i i)
{
  return _mm256_i32gather_epi32((const int *)(const void *)c->P, i, 1);
}
static inline void hash3(const p3ctx *c, vi X, vi Y, vi Z, vi h[8])
{
  const __m256i m = _mm256_set1_epi32(255);
  __m256i y = (__m256i)Y, z = (__m256i)Z;
  __m256i g1 = gat(c, _mm256_and_si256((__m256i)X, m));
  __m256i A = _mm256_and_si256(_mm256_add_epi32(g1, y), m);
  __m256i B = _mm256_and_si256(_mm256_add_epi32(_mm256_srli_epi32(g1, 8), y), m);
  __m256i gA = gat(c, A), gB = gat(c, B);
  __m256i AA = _mm256_and_si256(_mm256_add_epi32(gA, z), m);
  __m256i AB = _mm256_and_si256(_mm256_add_epi32(_mm256_srli_epi32(gA, 8), z), m);
  __m256i BA = _mm256_and_si256(_mm256_add_epi32(gB, z), m);
  __m256i BB = _mm256_and_si256(_mm256_add_epi32(_mm256_srli_epi32(gB, 8), z), m);
  __m256i hAA = gat(c, AA), hAB = gat(c, AB), hBA = gat(c, BA), hBB = gat(c, BB);
  h[0] = (vi)hAA;
  h[1] = (vi)hAB;
  h[2] = (vi)_mm256_srli_epi32(hAA, 8);
  h[3] = (vi)_mm256_srli_epi32(hAB, 8);
  h[4] = (vi)hBA;
  h[5] = (vi)hBB;
  h[6] = (vi)_mm256_srli_epi32(hBA, 8);
  h[7] = (vi)_mm256_srli_epi32(hBB, 8);
}
static inline vf grad3(const p3ctx *c, int comp, vi h)
{
  __m256 lo = _mm256_permutevar8x32_ps(c->g[comp][0], (__m256i)h);
  __m256 hi = _mm256_permutevar8x32_ps(c->g[comp][1], (__m256i)h);
  return (vf)_mm256_blendv_ps(lo, hi, _mm256_castsi256_ps(_mm256_slli_epi32((__m256i)h, 28)));
}

static inline void g2_get(const nl_f32_g2 *g, vi cx, vi cy, vf gx[4], vf gy[4])
{
  const int *pp = (const int *)(const void *)g->pp;
  __m256i cy4 = _mm256_slli_epi32((__m256i)cy, 2);
  __m256i e[2];
  e[0] = _mm256_add_epi32(_mm256_i32gather_epi32(pp, (__m256i)cx, 4), cy4);
  e[1] = _mm256_add_epi32(_mm256_i32gather_epi32(pp, _mm256_add_epi32((__m256i)cx, _mm256_set1_epi32(1)), 4),
                          cy4);
  for (int col = 0; col < 2; col++) {
    gx[2 * col] = (vf)_mm256_i32gather_ps(g->g4, e[col], 4);
    gy[2 * col] = (vf)_mm256_i32gather_ps(g->g4 + 1, e[col], 4);
    gx[2 * col + 1] = (vf)_mm256_i32gather_ps(g->g4 + 2, e[col], 4);
    gy[2 * col + 1] = (vf)_mm256_i32gather_ps(g->g4 + 3, e[col], 4);
  }
}

static inline vf win_get(const vf w[2], vi idx)
{
  __m256 lo = _mm256_permutevar8x32_ps((__m256)w[0], (__m256i)idx);
  __m256 hi = _mm256_permutevar8x32_ps((__m256)w[1], (__m256i)idx);
  return (vf)_mm256_blendv_ps(lo, hi, _mm256_castsi256_ps(_mm256_slli_epi32((__m256i)idx, 28)));
}

#include "noise/nl_noise_f32_body.h"

const nl_f32_kernels nl_noise_f32_avx2 = {p3_points, p3_row, g2_points, g2_row};

#if defined(__clang__)
#pragma clang attribute pop
#endif
