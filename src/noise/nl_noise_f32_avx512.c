/* nl_noise_f32_avx512.c - the float32 kernels (nl_noise_f32_body.h) for
 * AVX-512 (F, DQ, BW, VL, VBMI, as the library's AVX-512 level) with FMA,
 * 16 floats a vector. Compiled with a target pragma, never -march: called
 * only when the dispatcher has seen the CPU support it.
 *
 * Perlin's table lives in four registers and is read with VBMI byte
 * permutes (vpermi2b), as the double kernels read it, but four lookups to
 * a lane: the hashes of a point's column pair (X, X + 1), then of its four
 * (A, A + 1, B, B + 1), then of the eight corners as two sets of four, are
 * the four bytes of each 32-bit lane, and byte adds wrap mod 256 as the
 * doubled table does. Four permute rounds hash 16 points where one lookup
 * a lane would take fourteen. His 16 gradients are one register per
 * component (vpermps reads the low 4 bits of the hash). */
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2,fma"))), apply_to = function)
#else
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx2,fma")
#endif
#include <immintrin.h>

#include "noise/nl_noise_f32_impl.h"

#define W 16
typedef float vf __attribute__((vector_size(64)));
typedef int vi __attribute__((vector_size(64)));

#define NLF_FMA(a, b, c) ((vf)_mm512_fmadd_ps((__m512)(a), (__m512)(b), (__m512)(c)))
#define NLF_C(k) ((vf)_mm512_set1_ps(k))

static inline vf v_floor(vf x)
{
  return (vf)_mm512_roundscale_ps((__m512)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
static inline vi v_cvtt(vf x) { return (vi)_mm512_cvttps_epi32((__m512)x); }
static inline vf v_i2f(vi x) { return (vf)_mm512_cvtepi32_ps((__m512i)x); }
static inline vf v_abs(vf x) { return (vf)_mm512_abs_ps((__m512)x); }
static inline vi vi_c(int k) { return (vi)_mm512_set1_epi32(k); }
static inline vf v_load(const float *p) { return (vf)_mm512_loadu_ps(p); }
static inline void v_store(float *p, vf v) { _mm512_storeu_ps(p, (__m512)v); }

typedef struct { __m512i t[4]; __m512 g[3]; } p3ctx;
static inline p3ctx p3ctx_make(const nl_noise_perm3 *p)
{
  p3ctx c;
  for (int q = 0; q < 4; q++) c.t[q] = _mm512_loadu_si512(p->p + 64 * q);
  for (int k = 0; k < 3; k++) c.g[k] = _mm512_loadu_ps(nl_noise_f32_g3[k]);
  return c;
}
/* P[b] for every byte b of ix (bit 7 picks the register pair) */
static inline __m512i lut(const p3ctx *c, __m512i ix)
{
  __m512i lo = _mm512_permutex2var_epi8(c->t[0], ix, c->t[1]);
  __m512i hi = _mm512_permutex2var_epi8(c->t[2], ix, c->t[3]);
  return _mm512_mask_blend_epi8(_mm512_movepi8_mask(ix), lo, hi);
}
static inline void hash3(const p3ctx *c, vi X, vi Y, vi Z, vi h[8])
{
  const __m512i b0 = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12, 12));
  const __m512i b01 = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 0, 1, 1, 4, 4, 5, 5, 8, 8, 9, 9, 12, 12, 13, 13));
  const __m512i inc = _mm512_set1_epi32(0x01000100);   /* bytes 0, 1, 0, 1 */
  __m512i x = _mm512_add_epi8(_mm512_shuffle_epi8((__m512i)X, b0), inc);        /* X, X+1 */
  __m512i h1 = lut(c, x);                                                      /* P[X], P[X+1] */
  __m512i y = _mm512_add_epi8(_mm512_shuffle_epi8((__m512i)Y, b0), inc);
  __m512i a = _mm512_add_epi8(_mm512_shuffle_epi8(h1, b01), y);                /* A, A+1, B, B+1 */
  __m512i h2 = lut(c, a);
  __m512i z0 = _mm512_add_epi8(h2, _mm512_shuffle_epi8((__m512i)Z, b0));       /* AA, AB, BA, BB */
  __m512i z1 = _mm512_add_epi8(z0, _mm512_set1_epi8(1));
  __m512i h3 = lut(c, z0), h4 = lut(c, z1);
  h[0] = (vi)h3;
  h[1] = (vi)_mm512_srli_epi32(h3, 8);
  h[2] = (vi)h4;
  h[3] = (vi)_mm512_srli_epi32(h4, 8);
  h[4] = (vi)_mm512_srli_epi32(h3, 16);
  h[5] = (vi)_mm512_srli_epi32(h3, 24);
  h[6] = (vi)_mm512_srli_epi32(h4, 16);
  h[7] = (vi)_mm512_srli_epi32(h4, 24);
}
static inline vf grad3(const p3ctx *c, int comp, vi h)
{
  return (vf)_mm512_permutexvar_ps((__m512i)h, c->g[comp]);
}

/* The batch tables lane by lane (a gather costs more than its loads one
 * by one): point q's two corners of a column, one 16-byte entry of g4,
 * go to quarter q / 4 of register q mod 4; a 4 x 4 transpose within each
 * quarter then leaves gx and gy of both corners with point q in lane q. */
/* a masked broadcast from memory: one load and one blend, where a
 * register insert would run on the shuffle port */
#define G2_INSERT(r, k, ptr) (r) = _mm512_mask_broadcast_f32x4((r), (__mmask16)(0xFu << (4 * (k))), _mm_loadu_ps(ptr))
static inline __attribute__((always_inline)) void g2_get(const nl_f32_g2 *g, vi cx, vi cy, vf gx[4],
                                                         vf gy[4])
{
  const uint32_t *pp = g->pp;
  const float *G = g->g4;
  __m512 r[2][4];
  if (g->m <= (1u << 14)) {
    /* i and 4 j share a 32-bit lane: lanes 4c .. 4c + 3 leave the register
     * as two 64-bit moves of chunk c (few uops on the vector ports, which
     * the arithmetic needs) */
    __m512i u = _mm512_or_si512((__m512i)cx, _mm512_slli_epi32((__m512i)cy, 18));
#define G2_LANE(d, k, c)                                                       \
  do {                                                                         \
    const uint32_t *pi_ = pp + ((d) & 0xffffu);                                \
    uint32_t j4_ = (uint32_t)(d) >> 16;                                        \
    const float *gj_ = G + j4_, *e0_ = gj_ + pi_[0], *e1_ = gj_ + pi_[1];     \
    if ((c) == 0) {                                                            \
      r[0][k] = _mm512_castps128_ps512(_mm_loadu_ps(e0_));                     \
      r[1][k] = _mm512_castps128_ps512(_mm_loadu_ps(e1_));                     \
    } else {                                                                   \
      G2_INSERT(r[0][k], (c), e0_);                                            \
      G2_INSERT(r[1][k], (c), e1_);                                            \
    }                                                                          \
  } while (0)
#define G2_CHUNK(c)                                                            \
  do {                                                                         \
    __m128i x_ = _mm512_extracti32x4_epi32(u, (c));                            \
    uint64_t a_ = (uint64_t)_mm_cvtsi128_si64(x_), b_ = (uint64_t)_mm_extract_epi64(x_, 1); \
    G2_LANE((uint32_t)a_, 0, c);                                               \
    G2_LANE((uint32_t)(a_ >> 32), 1, c);                                       \
    G2_LANE((uint32_t)b_, 2, c);                                               \
    G2_LANE((uint32_t)(b_ >> 32), 3, c);                                       \
  } while (0)
    G2_CHUNK(0);
    G2_CHUNK(1);
    G2_CHUNK(2);
    G2_CHUNK(3);
#undef G2_CHUNK
#undef G2_LANE
  } else {
    int ci[W], cj[W];
    _mm512_storeu_si512(ci, (__m512i)cx);
    _mm512_storeu_si512(cj, _mm512_slli_epi32((__m512i)cy, 2));
    for (int rr = 0; rr < 4; rr++) {
      const float *e[2][4];
      for (int k = 0; k < 4; k++) {
        int q = 4 * k + rr;
        const uint32_t *pi = pp + (uint32_t)ci[q];   /* (P[i], P[i + 1]): one base */
        uint32_t j4 = (uint32_t)cj[q];
        e[0][k] = G + (pi[0] + j4);
        e[1][k] = G + (pi[1] + j4);
      }
      for (int col = 0; col < 2; col++) {
        __m512 v = _mm512_castps128_ps512(_mm_loadu_ps(e[col][0]));
        G2_INSERT(v, 1, e[col][1]);
        G2_INSERT(v, 2, e[col][2]);
        G2_INSERT(v, 3, e[col][3]);
        r[col][rr] = v;
      }
    }
  }
  for (int col = 0; col < 2; col++) {
    __m512 t0 = _mm512_unpacklo_ps(r[col][0], r[col][1]), t1 = _mm512_unpackhi_ps(r[col][0], r[col][1]);
    __m512 t2 = _mm512_unpacklo_ps(r[col][2], r[col][3]), t3 = _mm512_unpackhi_ps(r[col][2], r[col][3]);
    gx[2 * col] = (vf)_mm512_castpd_ps(_mm512_unpacklo_pd(_mm512_castps_pd(t0), _mm512_castps_pd(t2)));
    gy[2 * col] = (vf)_mm512_castpd_ps(_mm512_unpackhi_pd(_mm512_castps_pd(t0), _mm512_castps_pd(t2)));
    gx[2 * col + 1] = (vf)_mm512_castpd_ps(_mm512_unpacklo_pd(_mm512_castps_pd(t1), _mm512_castps_pd(t3)));
    gy[2 * col + 1] = (vf)_mm512_castpd_ps(_mm512_unpackhi_pd(_mm512_castps_pd(t1), _mm512_castps_pd(t3)));
  }
}

static inline vf win_get(const vf w[2], vi idx)
{
  return (vf)_mm512_permutex2var_ps((__m512)w[0], (__m512i)idx, (__m512)w[1]);
}

#include "noise/nl_noise_f32_body.h"

const nl_f32_kernels nl_noise_f32_avx512 = {p3_points, p3_row, g2_points, g2_row};

#if defined(__clang__)
#pragma clang attribute pop
#endif
