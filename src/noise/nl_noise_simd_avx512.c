/* nl_noise_simd_avx512.c - the kernels of nl_noise_simd_body.h for AVX-512
 * (F, DQ, BW, VL and VBMI: Ice Lake, Zen 4 and later), 8 doubles a vector.
 * Compiled with a target pragma, never -march: called only when the
 * dispatcher has seen the CPU (and the OS) support it. No FMA: see
 * nl_noise_simd.h.
 *
 * Memory lookups are what limit these kernels (a gather of 8 doubles takes
 * about 13 cycles on AMD Zen 4, more than its loads one by one), so the
 * tables that fit live in registers: Perlin's 256-entry permutation in four
 * (VBMI byte permutes, 64 lookups each in the batches and row columns,
 * which hash in bytes), his 16 gradients in two per component (vpermt2pd),
 * and the sample loop of a row reads its columns through a window of 8 or
 * 16 loaded once per 8 samples (vpermpd, vpermt2pd). The 2D table of a
 * batch is folded with its permutation into pairs read by 16-byte loads.
 */
#include "simd/nl_simd_avx512.h"   /* vd, vl, v_floor, v_ceil, v_all */
#include "noise/nl_noise_simd.h"
#include <math.h>
#include <string.h>

#define NL_SIMD_W 8
#define NL_SIMD_TABLE nl_noise_simd_avx512
typedef int vi __attribute__((vector_size(32)));
typedef unsigned vu __attribute__((vector_size(32)));

/* Lookups lane by lane (the 2D tables are too big for registers). */
#include "simd/nl_simd_lanes.h"

#define NL_SIMD_HAVE_TABLES
typedef struct { __m512i p[4]; __m512d g[3][2]; } p3tab;
static inline p3tab p3_make(const nl_noise_perm3 *P, const int *p32)
{
  (void)p32;
  p3tab t;
  for (int q = 0; q < 4; q++) t.p[q] = _mm512_loadu_si512(P->p + 64 * q);
  for (int c = 0; c < 3; c++) {
    t.g[c][0] = _mm512_loadu_pd(nl_noise_simd_g3[c]);
    t.g[c][1] = _mm512_loadu_pd(nl_noise_simd_g3[c] + 8);
  }
  return t;
}
/* p[idx] for idx < 512 of a doubled table: byte 0 of each int lane indexes
 * (low 7 bits into a 128-byte pair, bit 7 picks the pair); bit 8 and the
 * upper bytes' lookups are dropped with the & 255. */
static inline vi p3_get(const p3tab *t, vi idx)
{
  __m512i ix = _mm512_castsi256_si512((__m256i)idx);
  __m512i lo = _mm512_permutex2var_epi8(t->p[0], ix, t->p[1]);
  __m512i hi = _mm512_permutex2var_epi8(t->p[2], ix, t->p[3]);
  __m512i r = _mm512_mask_blend_epi8(_mm512_movepi8_mask(ix), lo, hi);
  return (vi)_mm512_castsi512_si256(r) & 255;
}
static inline vd g3(const p3tab *t, int comp, vi h)
{
  return (vd)_mm512_permutex2var_pd(t->g[comp][0], _mm512_cvtepi32_epi64((__m256i)h), t->g[comp][1]);
}

/* eq. 5.4's packing (nl_noise_simd_body.h) by compress: the undecided
 * lanes of each array, compressed in a register, stored as a whole vector
 * at left (the lanes past the kept ones land on points already read). */
#define NL_SIMD_HAVE_COMPRESS
static inline size_t v_pack(const nl_noise_pack *pk, size_t k, vd x, vd y, vd z, vd b, vd sum, double r,
                            size_t left, int *hi, size_t *nh)
{
  vd s = b + sum;
  __mmask8 lo = _mm512_cmp_pd_mask((__m512d)(s + r), _mm512_setzero_pd(), _CMP_LE_OQ);
  __mmask8 up = _mm512_cmp_pd_mask((__m512d)(s - r), _mm512_set1_pd(1.0), _CMP_GE_OQ);
  __mmask8 keep = (__mmask8)~(lo | up);
  __m256i id = _mm256_loadu_si256((const __m256i *)(pk->id + k));
  for (unsigned m = up; m; m &= m - 1) hi[(*nh)++] = pk->id[k + (size_t)__builtin_ctz(m)];
  _mm512_storeu_pd(pk->x + left, _mm512_maskz_compress_pd(keep, (__m512d)x));
  _mm512_storeu_pd(pk->y + left, _mm512_maskz_compress_pd(keep, (__m512d)y));
  _mm512_storeu_pd(pk->z + left, _mm512_maskz_compress_pd(keep, (__m512d)z));
  _mm512_storeu_pd(pk->base + left, _mm512_maskz_compress_pd(keep, (__m512d)b));
  _mm512_storeu_pd(pk->sum + left, _mm512_maskz_compress_pd(keep, (__m512d)sum));
  _mm256_storeu_si256((__m256i *)(pk->id + left), _mm256_maskz_compress_epi32(keep, id));
  return left + (size_t)__builtin_popcount(keep);
}

#include "noise/nl_noise_simd_body.h"

/* The row's sample loop with a window: while 8 consecutive samples span at
 * most 7 columns (7 |dx| <= 4 leaves room for the rounding of x, whose ulp
 * is at most 1/2 below 2^52), the columns they use are gx[b .. b + 7] for
 * b the lowest of them, and gx[b + 1 .. b + 8] for the right-hand ones.
 * The column arrays are padded for the load past the last column.
 * plain: no x is -0 (so no cell is -0): v_cell's +0 changes nothing there
 * and is left out (same bits, one operation fewer per 8 samples). */
static inline __attribute__((always_inline)) void
samples_win(const double *gx, const double *a, long ifirst, double x0, double dx, size_t n,
            double *out, int mode, double amp, int plain, int rev)
{
  vd kv, vfirst = SPLAT((double)ifirst);
  for (int l = 0; l < NL_SIMD_W; l++) kv[l] = l;
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    vd x = kv * dx + x0;                  /* x0 + (double)k * dx */
    vd cell = plain ? v_floor(x) : v_cell(x);
    vd c = cell - vfirst;                 /* lfloor(x) - ifirst, exact */
    /* the lowest column: lane 0, or lane 7 when dx < 0 (rev), kept in
     * registers (a round trip through memory stalls the loads below) */
    __m128d lane = _mm512_castpd512_pd128((__m512d)c);
    if (rev) { __m128d q = _mm512_extractf64x2_pd((__m512d)c, 3); lane = _mm_unpackhi_pd(q, q); }
    long b = _mm_cvttsd_si64(lane);
    __m512i li = _mm512_cvttpd_epi64(_mm512_sub_pd((__m512d)c, _mm512_broadcastsd_pd(lane)));
    vd g0 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(gx + b));
    vd a0 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(a + b));
    vd g1 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(gx + b + 1));
    vd a1 = (vd)_mm512_permutexvar_pd(li, _mm512_loadu_pd(a + b + 1));
    vd v = v_blend(v_frac(x, cell), g0, a0, g1, a1);
    st(out + k, v_emit(out + k, v, mode, amp));
  }
  if (k < n) samples_tail(gx, a, ifirst, x0, dx, k, n, out, mode, amp);
}

/* samples_win for sparser rows: while 7 |dx| <= 13, 8 consecutive samples
 * span at most 15 columns with their right-hand ones (cells at most 14
 * apart, as above), so two vectors of columns from the lowest serve both
 * sides through two-table permutes (vpermt2pd), the right-hand side at
 * index + 1. A row with 0.7 cells per sample reads its columns this way,
 * not lane by lane. */
static inline __attribute__((always_inline)) void
samples_win16(const double *gx, const double *a, long ifirst, double x0, double dx, size_t n,
              double *out, int mode, double amp, int plain, int rev)
{
  vd kv;
  for (int l = 0; l < NL_SIMD_W; l++) kv[l] = l;
  __m512i one = _mm512_set1_epi64(1);
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    vd x = kv * dx + x0;                  /* x0 + (double)k * dx */
    vd cell = plain ? v_floor(x) : v_cell(x);
    /* the lowest cell: lane 0, or lane 7 when dx < 0 (rev) */
    __m128d lane = _mm512_castpd512_pd128((__m512d)cell);
    if (rev) {
      __m128d q = _mm512_extractf64x2_pd((__m512d)cell, 3);
      lane = _mm_unpackhi_pd(q, q);
    }
    long b = _mm_cvttsd_si64(lane) - ifirst;
    __m512i li = _mm512_cvttpd_epi64(_mm512_sub_pd((__m512d)cell, _mm512_broadcastsd_pd(lane)));
    __m512i li1 = _mm512_add_epi64(li, one);
    __m512d G0 = _mm512_loadu_pd(gx + b), G1 = _mm512_loadu_pd(gx + b + 8);
    __m512d A0 = _mm512_loadu_pd(a + b), A1 = _mm512_loadu_pd(a + b + 8);
    vd g0 = (vd)_mm512_permutex2var_pd(G0, li, G1), a0 = (vd)_mm512_permutex2var_pd(A0, li, A1);
    vd g1 = (vd)_mm512_permutex2var_pd(G0, li1, G1), a1 = (vd)_mm512_permutex2var_pd(A0, li1, A1);
    vd v = v_blend(v_frac(x, cell), g0, a0, g1, a1);
    st(out + k, v_emit(out + k, v, mode, amp));
  }
  if (k < n) samples_tail(gx, a, ifirst, x0, dx, k, n, out, mode, amp);
}

static void samples(const double *gx, const double *a, long ifirst, double x0, double dx,
                    size_t n, double *out, int mode, double amp)
{
  if (!(fabs(dx) * 7 <= 4)) {
    int plain = !(x0 == 0 && signbit(x0));
    if (!(fabs(dx) * 7 <= 13)) samples_lanes(gx, a, ifirst, x0, dx, n, out, mode, amp);
    else if (dx >= 0 && plain) samples_win16(gx, a, ifirst, x0, dx, n, out, mode, amp, 1, 0);
    else if (dx >= 0) samples_win16(gx, a, ifirst, x0, dx, n, out, mode, amp, 0, 0);
    else if (plain) samples_win16(gx, a, ifirst, x0, dx, n, out, mode, amp, 1, 1);
    else samples_win16(gx, a, ifirst, x0, dx, n, out, mode, amp, 0, 1);
    return;
  }
  int plain = !(x0 == 0 && signbit(x0));   /* x = k dx + x0 is -0 only for x0 = -0 */
  if (dx >= 0) {
    if (plain) samples_win(gx, a, ifirst, x0, dx, n, out, mode, amp, 1, 0);
    else samples_win(gx, a, ifirst, x0, dx, n, out, mode, amp, 0, 0);
  } else {
    if (plain) samples_win(gx, a, ifirst, x0, dx, n, out, mode, amp, 1, 1);
    else samples_win(gx, a, ifirst, x0, dx, n, out, mode, amp, 0, 1);
  }
}

/* Points 16 at a time: the byte permutes of the hashing fill a whole
 * register of 16 int lanes; the arithmetic runs on two halves of 8 doubles. */
typedef int vi16 __attribute__((vector_size(64)));
static inline vi16 p3_get16(const p3tab *t, vi16 idx)
{
  __m512i ix = (__m512i)idx;
  __m512i lo = _mm512_permutex2var_epi8(t->p[0], ix, t->p[1]);
  __m512i hi = _mm512_permutex2var_epi8(t->p[2], ix, t->p[3]);
  return (vi16)_mm512_mask_blend_epi8(_mm512_movepi8_mask(ix), lo, hi) & 255;
}
static inline vi16 join(vi lo, vi hi)
{
  return (vi16)_mm512_inserti64x4(_mm512_castsi256_si512((__m256i)lo), (__m256i)hi, 1);
}
static inline vi half(vi16 v, int h)
{
  return h ? (vi)_mm512_extracti64x4_epi64((__m512i)v, 1) : (vi)_mm512_castsi512_si256((__m512i)v);
}

/* Perlin's hashing of 16 points (nl_noise.c column3 for columns i and
 * i + 1), lanes of (x[h], y[h], z[h]) for h = 0, 1; 0 if a lane leaves
 * |.| < 2^31 (then nothing is hashed). */
static inline __attribute__((always_inline)) int
hash16(const p3tab *tab, const vd *x, const vd *y, const vd *z, vi16 hs[2][4])
{
  vl ok = (vl){0} - 1;
  vi i[2], j[2], kk[2];
  for (int h = 0; h < 2; h++) {
    ok &= v_small(x[h]) & v_small(y[h]) & v_small(z[h]);
    i[h] = __builtin_convertvector(v_cell(x[h]), vi);
    j[h] = __builtin_convertvector(v_cell(y[h]), vi);
    kk[h] = __builtin_convertvector(v_cell(z[h]), vi);
  }
  if (!v_all(ok)) return 0;
  vi16 I = join(i[0], i[1]), Y = join(j[0], j[1]) & 255, Z = join(kk[0], kk[1]) & 255;
  for (int c = 0; c < 2; c++) {
    vi16 X = (vi16)(((unsigned)c + (__attribute__((vector_size(64))) unsigned)I) & 255u);
    vi16 A = p3_get16(tab, X) + Y, AA = p3_get16(tab, A) + Z, AB = p3_get16(tab, A + 1) + Z;
    hs[c][0] = p3_get16(tab, AA) & 15; hs[c][1] = p3_get16(tab, AB) & 15;
    hs[c][2] = p3_get16(tab, AA + 1) & 15; hs[c][3] = p3_get16(tab, AB + 1) & 15;
  }
  return 1;
}

/* The arithmetic of half h of a hashed 16 (the cells again rather than kept). */
static inline __attribute__((always_inline)) vd
arith8(const p3tab *tab, vi16 hs[2][4], int h, vd vx, vd vy, vd vz)
{
  vd ci = v_cell(vx), fy = v_frac(vy, v_cell(vy)), fz = v_frac(vz, v_cell(vz));
  vd v = v_fade(fy), w = v_fade(fz), g0, a0, g1, a1;
  v_column3_fp(tab, half(hs[0][0], h), half(hs[0][1], h), half(hs[0][2], h), half(hs[0][3], h),
               fy, fz, v, w, &g0, &a0);
  v_column3_fp(tab, half(hs[1][0], h), half(hs[1][1], h), half(hs[1][2], h), half(hs[1][3], h),
               fy, fz, v, w, &g1, &a1);
  return v_blend(v_frac(vx, ci), g0, a0, g1, a1);
}

/* ---- 64 points (or columns) per byte permute ------------------------------
 *
 * With a doubled table p[idx] = p[idx & 255], so Perlin's hashing is byte
 * arithmetic: A = p[X] + Y and the sums after it may wrap mod 256 without
 * changing a lookup, and X + 1 may too. One lookup of 64 byte lanes then
 * serves 64 points, where int lanes serve 16: the 14 lookups of a point
 * fall from 56 permutes per 16 points to 56 per 64. The corner hashes go
 * through memory in a transposed order: byte 8 l + g of a corner's row
 * holds point 8 g + l, so one 64-byte load at byte g gives qword l the
 * hash of point 8 g + l in its low byte, and that load is the index of
 * the gradient permutes (vpermt2pd reads the low 4 bits: the & 15 is
 * free). Widening 8 hashes to qwords instead took a shuffle per corner
 * from the pipes the permutes and the arithmetic share (5% of a batch
 * on Zen 4). */
typedef unsigned char vb __attribute__((vector_size(64)));   /* wraps mod 256 */
/* p[idx]: the lanes with bit 7 set look up the upper 128 entries in place
 * (vpermi2b keeps the index where the mask is clear), then the others the
 * lower 128: no blend. */
static inline vb p3_byte(const p3tab *t, vb idx)
{
  __m512i ix = (__m512i)idx;
  __mmask64 up = _mm512_movepi8_mask(ix);
  __m512i r = _mm512_mask2_permutex2var_epi8(t->p[2], ix, up, t->p[3]);
  return (vb)_mm512_mask2_permutex2var_epi8(t->p[0], r, (__mmask64)~up, t->p[1]);
}
/* Hashes 8 q .. 8 q + 7 of a byte array, widened to qwords. */
static inline __m512i widen8(const unsigned char *h)
{
  return _mm512_cvtepu8_epi64(_mm_loadl_epi64((const __m128i *)h));
}
static inline vd g3q(const p3tab *t, int comp, __m512i h)
{
  return (vd)_mm512_permutex2var_pd(t->g[comp][0], h, t->g[comp][1]);
}
/* v_column3_fp (nl_noise_simd_body.h), the same operations in the same
 * order, on widened hashes. */
static inline __attribute__((always_inline)) void
column3_q(const p3tab *p, __m512i h00, __m512i h10, __m512i h01, __m512i h11, vd fy, vd fz, vd v,
          vd w, vd *gxo, vd *ao)
{
  *gxo = v_lerp(w, v_lerp(v, g3q(p, 0, h00), g3q(p, 0, h10)),
                v_lerp(v, g3q(p, 0, h01), g3q(p, 0, h11)));
  vd fy1 = fy - 1.0, fz1 = fz - 1.0;
  vd y00 = g3q(p, 1, h00) * fy + g3q(p, 2, h00) * fz;
  vd y10 = g3q(p, 1, h10) * fy1 + g3q(p, 2, h10) * fz;
  vd y01 = g3q(p, 1, h01) * fy + g3q(p, 2, h01) * fz1;
  vd y11 = g3q(p, 1, h11) * fy1 + g3q(p, 2, h11) * fz1;
  *ao = v_lerp(w, v_lerp(v, y00, y10), v_lerp(v, y01, y11));
}

/* Perlin's hashing (nl_noise.c column3 at columns i and i + 1) of the 64
 * points of bytes X, Y, Z: the corner hashes h00, h10, h01, h11 of column
 * i to hs[0 .. 3], of column i + 1 to hs[4 .. 7]. */
static inline __attribute__((always_inline)) void
hash64(const p3tab *tab, vb X, vb Y, vb Z, unsigned char hs[8][64])
{
  for (int c = 0; c < 2; c++) {
    vb A = p3_byte(tab, X + (unsigned char)c) + Y;
    vb AA = p3_byte(tab, A) + Z, AB = p3_byte(tab, A + 1) + Z;
    vb h[4] = {p3_byte(tab, AA), p3_byte(tab, AB), p3_byte(tab, AA + 1), p3_byte(tab, AB + 1)};
    memcpy(hs[4 * c], h, sizeof h);
  }
}

/* nl_noise.c column3 for columns ifirst + c, c < ncol, of a row at (y, z)
 * (columns3 of nl_noise_simd_body.h), hashed 64 columns at a time: X =
 * xm + c in bytes wraps as the lookups do. */
static void columns3_64(const nl_noise_perm3 *P, const int *p32, unsigned xm, unsigned ym,
                        unsigned zm, double fy, double fz, double v, double w, size_t ncol,
                        double *gxo, double *ao)
{
  p3tab tab = p3_make(P, p32);
  vb iota, Y, Z;
  for (int l = 0; l < 64; l++) {
    iota[l] = (unsigned char)l;
    Y[l] = (unsigned char)ym;
    Z[l] = (unsigned char)zm;
  }
  /* A row's corners have fixed fractions in y and z, so each corner's
   * yz_part (nl_noise.c) is a function of its hash alone: 16 values,
   * made once here with the same operations, looked up per column. The
   * corners q = dj + 2 dk, as v_column3_fp's y00, y10, y01, y11. */
  double fys[2] = {fy, fy - 1}, fzs[2] = {fz, fz - 1};
  __m512d yz[4][2];
  for (int q = 0; q < 4; q++)
    for (int h = 0; h < 2; h++)
      yz[q][h] = (__m512d)((vd)tab.g[1][h] * fys[q & 1] + (vd)tab.g[2][h] * fzs[q >> 1]);
  vd vv = SPLAT(v), vw = SPLAT(w);
  for (size_t c = 0; c < ncol; c += 64) {
    unsigned char hs[4][64] __attribute__((aligned(64)));
    vb A = p3_byte(&tab, iota + (unsigned char)(xm + c)) + Y;
    vb AA = p3_byte(&tab, A) + Z, AB = p3_byte(&tab, A + 1) + Z;
    vb h[4] = {p3_byte(&tab, AA), p3_byte(&tab, AB), p3_byte(&tab, AA + 1), p3_byte(&tab, AB + 1)};
    memcpy(hs, h, sizeof h);
    size_t ng = ncol - c < 64 ? (ncol - c) / 8 : 8;
    for (size_t q = 0; q < ng; q++) {
      __m512i h[4];
      vd y[4];
      for (int e = 0; e < 4; e++) {
        h[e] = widen8(hs[e] + 8 * q);
        y[e] = (vd)_mm512_permutex2var_pd(yz[e][0], h[e], yz[e][1]);
      }
      /* the rest of v_column3_fp */
      vd g = v_lerp(vw, v_lerp(vv, g3q(&tab, 0, h[0]), g3q(&tab, 0, h[1])),
                    v_lerp(vv, g3q(&tab, 0, h[2]), g3q(&tab, 0, h[3])));
      st(gxo + c + 8 * q, g);
      st(ao + c + 8 * q, v_lerp(vw, v_lerp(vv, y[0], y[1]), v_lerp(vv, y[2], y[3])));
    }
  }
}

/* The cells of 8 coordinates as ints: floor by the conversion's rounding
 * mode. A coordinate outside [-2^31, 2^31), NaN or infinite converts to
 * INT_MIN, which the caller takes as "not here" (with the few coordinates
 * whose floor is INT_MIN itself: the scalar code takes them all). */
static inline __m256i cell_ints(vd x)
{
  return _mm512_cvt_roundpd_epi32((__m512d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

/* The low bytes of 16 cells (two vectors of 8 int lanes: points 16 h ..
 * 16 h + 7 in the first, byte 4 l, and the next 8 in the second, byte
 * 64 + 4 l of vpermt2b's pair) to their transposed places among 64 (byte
 * 8 l + g for point 8 g + l), in one permute. tr_mask[h]: the places of
 * points 16 h .. 16 h + 15, g = 2 h and 2 h + 1. */
#define TR_P(i, h) (8 * ((i) & 7) + ((i) >> 3) - 16 * (h))
#define TR_B(i, h) (TR_P(i, h) >= 0 && TR_P(i, h) < 8 ? 4 * TR_P(i, h)             \
                    : TR_P(i, h) >= 8 && TR_P(i, h) < 16 ? 64 + 4 * (TR_P(i, h) - 8) \
                    : 0)
#define TR_8(i, h) TR_B(i, h), TR_B(i + 1, h), TR_B(i + 2, h), TR_B(i + 3, h), \
                   TR_B(i + 4, h), TR_B(i + 5, h), TR_B(i + 6, h), TR_B(i + 7, h)
#define TR_64(h) {TR_8(0, h), TR_8(8, h), TR_8(16, h), TR_8(24, h), \
                  TR_8(32, h), TR_8(40, h), TR_8(48, h), TR_8(56, h)}
static const unsigned char tr_ix[4][64] __attribute__((aligned(64))) = {
    TR_64(0), TR_64(1), TR_64(2), TR_64(3)};
static const __mmask64 tr_mask[4] = {0x0303030303030303ull, 0x0c0c0c0c0c0c0c0cull,
                                     0x3030303030303030ull, 0xc0c0c0c0c0c0c0c0ull};

/* The 8 corner rows of a hashed 64 (hash64), and a ninth that hash_ix's
 * loads at byte g of the last row reach 7 bytes into: cleared once by
 * the caller, read, never used. */
typedef struct { unsigned char row[9][64]; } __attribute__((aligned(64))) p3rows;

/* The fractions of 64 points and their hashes, transposed (hash64): the
 * hashing runs on the cells' bytes in that order. 0 if a coordinate has no
 * int cell (then nothing is hashed). lfloor as the int cell converted back
 * (exact, and +0 for -0, as the scalar (double)i), so the fraction is the
 * scalar one. The fades are made where they are used: on Zen 4 a 64-byte
 * store takes two cycles of the one store unit, and storing three fades
 * per 8 points cost more than making them again (4% of the batch). */
static inline __attribute__((always_inline)) int
points_hash64(const p3tab *tab, double f, int scale, const double *x, const double *y,
              const double *z, double fr[3][64], p3rows *hs)
{
  const double *src[3] = {x, y, z};
  __mmask8 bad = 0;
  vb b[3];
  for (int a = 0; a < 3; a++) {
    __m512i w = _mm512_setzero_si512();
    for (int h = 0; h < 4; h++) {
      __m256i ci[2];
      for (int u = 0; u < 2; u++) {
        int g = 2 * h + u;
        vd v = ld(src[a] + 8 * g);
        if (scale) v = f * v;   /* f * x[k] ... */
        ci[u] = cell_ints(v);
        vd t = v - (vd)_mm512_cvtepi32_pd(ci[u]);
        st(fr[a] + 8 * g, t);
        bad |= _mm256_cmpeq_epi32_mask(ci[u], _mm256_set1_epi32((int)0x80000000u));
      }
      __m512i ix = _mm512_load_si512(tr_ix[h]);
      w |= _mm512_maskz_permutex2var_epi8(tr_mask[h], _mm512_castsi256_si512(ci[0]), ix,
                                          _mm512_castsi256_si512(ci[1]));
    }
    b[a] = (vb)w;
  }
  if (bad) return 0;
  hash64(tab, b[0], b[1], b[2], hs->row);
  return 1;
}

/* The gradient index of points 8 g .. 8 g + 7 at one corner (hash64):
 * bytes g .. g + 63 of its row (p3rows). */
static inline __m512i hash_ix(const unsigned char *row, int g)
{
  return _mm512_loadu_si512(row + g);
}
/* Points 8 g .. 8 g + 7 of a hashed 64: nl_noise_perm3_eval from the
 * fractions (two columns, then nl_noise.c's blend). */
static inline __attribute__((always_inline)) vd
points_arith64(const p3tab *tab, const double fr[3][64], const p3rows *hs, int g)
{
  vd fy = ld(fr[1] + 8 * g), fz = ld(fr[2] + 8 * g);
  vd v = v_fade(fy), w = v_fade(fz), g0, a0, g1, a1;
  const unsigned char(*r)[64] = hs->row;
  column3_q(tab, hash_ix(r[0], g), hash_ix(r[1], g), hash_ix(r[2], g), hash_ix(r[3], g), fy, fz, v,
            w, &g0, &a0);
  column3_q(tab, hash_ix(r[4], g), hash_ix(r[5], g), hash_ix(r[6], g), hash_ix(r[7], g), fy, fz, v,
            w, &g1, &a1);
  return v_blend(ld(fr[0] + 8 * g), g0, a0, g1, a1);
}

/* n points 16 at a time, stored or (sum) scaled by f and summed into out
 * as points3_do (nl_noise_simd_body.h). */
static inline __attribute__((always_inline)) int
points3_16(const nl_noise_perm3 *P, const int *p32, double f, const double *x, const double *y,
           const double *z, size_t n, double *out, double amp, double *top, int sum)
{
  p3tab tab = p3_make(P, p32);
  vd vt = SPLAT(0.0);
  size_t k = 0;
  int slow = 0;
  p3rows hs64;
  memset(hs64.row[8], 0, sizeof hs64.row[8]);
  for (; k + 64 <= n; k += 64) {
    double fr[3][64] __attribute__((aligned(64)));
    if (!points_hash64(&tab, f, sum, x + k, y + k, z + k, fr, &hs64)) {
      slow |= points3_do(P, p32, f, x + k, y + k, z + k, 64, out + k, amp, top, sum);
      continue;
    }
    for (int g = 0; g < 8; g++)
      v_points_emit(out + k + 8 * g, points_arith64(&tab, fr, &hs64, g), sum, amp, &vt);
  }
  for (; k + 16 <= n; k += 16) {
    vd sx[2], sy[2], sz[2];
    vi16 hs[2][4];
    for (int h = 0; h < 2; h++) {
      sx[h] = ld(x + k + 8 * h); sy[h] = ld(y + k + 8 * h); sz[h] = ld(z + k + 8 * h);
      if (sum) { sx[h] = f * sx[h]; sy[h] = f * sy[h]; sz[h] = f * sz[h]; }   /* f * x[k] ... */
    }
    if (!hash16(&tab, sx, sy, sz, hs)) {
      slow |= points3_do(P, p32, f, x + k, y + k, z + k, 16, out + k, amp, top, sum);
      continue;
    }
    for (int h = 0; h < 2; h++) {
      vd vx = ld(x + k + 8 * h), vy = ld(y + k + 8 * h), vz = ld(z + k + 8 * h);
      if (sum) { vx = f * vx; vy = f * vy; vz = f * vz; }
      v_points_emit(out + k + 8 * h, arith8(&tab, hs, h, vx, vy, vz), sum, amp, &vt);
    }
  }
  if (k < n) slow |= points3_do(P, p32, f, x + k, y + k, z + k, n - k, out + k, amp, top, sum);
  if (sum) *top = v_top(vt, *top);
  return slow;
}

static int points3(const nl_noise_perm3 *P, const int *p32, const double *x, const double *y,
                    const double *z, size_t n, double *out)
{
  return points3_16(P, p32, 1.0, x, y, z, n, out, 0.0, NULL, 0);
}

static int points3_sum(const nl_noise_perm3 *P, const int *p32, double f, const double *x,
                       const double *y, const double *z, size_t n, double amp, double *sum,
                       double *top)
{
  return points3_16(P, p32, f, x, y, z, n, sum, amp, top, 1);
}

/* The bounded term 16 at a time: each half packed as soon as it is summed
 * (its stores reach at most the half just read). */
static size_t points3_bounded(const nl_noise_perm3 *P, const int *p32, double f, double amp, double r,
                              const nl_noise_pack *pk0, size_t n, int *hi, size_t *nhi, double *top)
{
  nl_noise_pack q = *pk0;   /* a local copy: the stores into the arrays cannot change its pointers */
  const nl_noise_pack *pk = &q;
  p3tab tab = p3_make(P, p32);
  vd vt = SPLAT(0.0);
  size_t k = 0, left = 0;
  p3rows hs64;
  memset(hs64.row[8], 0, sizeof hs64.row[8]);
  for (; k + 64 <= n; k += 64) {   /* pass 1 reads the 64 before any is packed */
    double fr[3][64] __attribute__((aligned(64)));
    if (!points_hash64(&tab, f, 1, pk->x + k, pk->y + k, pk->z + k, fr, &hs64)) {
      left = points3_bounded_do(&tab, P, f, amp, r, pk, k, k + 64, left, hi, nhi, &vt);
      continue;
    }
    for (int g = 0; g < 8; g++) {
      size_t q = k + 8 * (size_t)g;
      vd v = points_arith64(&tab, fr, &hs64, g);
      v_top_raise(&vt, v);
      left = v_pack(pk, q, ld(pk->x + q), ld(pk->y + q), ld(pk->z + q), ld(pk->base + q),
                    ld(pk->sum + q) + amp * v, r, left, hi, nhi);
    }
  }
  for (; k + 16 <= n; k += 16) {
    vd sx[2], sy[2], sz[2];
    vi16 hs[2][4];
    for (int h = 0; h < 2; h++) {
      sx[h] = f * ld(pk->x + k + 8 * h); sy[h] = f * ld(pk->y + k + 8 * h); sz[h] = f * ld(pk->z + k + 8 * h);
    }
    if (!hash16(&tab, sx, sy, sz, hs)) {
      left = points3_bounded_do(&tab, P, f, amp, r, pk, k, k + 16, left, hi, nhi, &vt);
      continue;
    }
    for (int h = 0; h < 2; h++) {
      size_t q = k + 8 * (size_t)h;
      vd x = ld(pk->x + q), y = ld(pk->y + q), z = ld(pk->z + q);
      vd v = arith8(&tab, hs, h, f * x, f * y, f * z);
      v_top_raise(&vt, v);
      left = v_pack(pk, q, x, y, z, ld(pk->base + q), ld(pk->sum + q) + amp * v, r, left, hi, nhi);
    }
  }
  if (k < n) left = points3_bounded_do(&tab, P, f, amp, r, pk, k, n, left, hi, nhi, &vt);
  *top = v_top(vt, *top);
  return left;
}

/* ---- batches of the 2D table noise ----------------------------------------
 *
 * points2_fold (nl_noise_simd_body.h) with its tables: the permutation
 * folded into the gradients as pairs (gx, gy)[P[a]], read by one 16-byte
 * load per corner and lane and split into two vectors by two permutes.
 * Gathers in place of these loads were measured slower (1.56x the lane-by-
 * lane path against 2.5x). */

/* The pairs (QX[k], QY[k]) at 8 addresses: one 16-byte load each, then
 * split into the two vectors. */
static inline __attribute__((always_inline)) void
pairs8(const double *const q[8], vd *gx, vd *gy)
{
  __m512d lo = _mm512_castpd128_pd512(_mm_loadu_pd(q[0]));
  lo = _mm512_insertf64x2(lo, _mm_loadu_pd(q[1]), 1);
  lo = _mm512_insertf64x2(lo, _mm_loadu_pd(q[2]), 2);
  lo = _mm512_insertf64x2(lo, _mm_loadu_pd(q[3]), 3);
  __m512d hi = _mm512_castpd128_pd512(_mm_loadu_pd(q[4]));
  hi = _mm512_insertf64x2(hi, _mm_loadu_pd(q[5]), 1);
  hi = _mm512_insertf64x2(hi, _mm_loadu_pd(q[6]), 2);
  hi = _mm512_insertf64x2(hi, _mm_loadu_pd(q[7]), 3);
  *gx = (vd)_mm512_permutex2var_pd(lo, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), hi);
  *gy = (vd)_mm512_permutex2var_pd(lo, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), hi);
}

/* 8 points of nl_noise_grad2_eval from the tables of points2_q. The
 * indices are scalar work, lane by lane, beside the vector work. */
static inline __attribute__((always_inline)) vd
points2_q8(const unsigned *p2, const double *q2, unsigned mask, vd vx, vd vy)
{
  /* i = lfloor(x), j = lfloor(y), fy = lfrac(y, j), v = fade(fy) */
  __m256i ci = cell_ints(vx), cj = cell_ints(vy);
  vd fx = vx - (vd)_mm512_cvtepi32_pd(ci), fy = vy - (vd)_mm512_cvtepi32_pd(cj), v = v_fade(fy);
  unsigned is[8], js[8];
  _mm256_storeu_si256((__m256i *)is, ci);
  _mm256_storeu_si256((__m256i *)js, cj);
  const double *q[4][8];   /* corners (i + di, j + dj), q = dj + 2 di */
  for (int l = 0; l < 8; l++) {
    const unsigned *pi = p2 + (is[l] & mask);   /* P[i mod m], then P[(i + 1) mod m] */
    unsigned j = js[l], p0 = pi[0], p1 = pi[1];
    q[0][l] = q2 + 2 * ((p0 + j) & mask);
    q[1][l] = q2 + 2 * ((p0 + j + 1) & mask);
    q[2][l] = q2 + 2 * ((p1 + j) & mask);
    q[3][l] = q2 + 2 * ((p1 + j + 1) & mask);
  }
  /* column2 at i and i + 1, then blend(lfrac(x, i), ...), as points2 */
  vd fy1 = fy - 1.0, g00, g01, g10, g11, y00, y01, y10, y11;
  pairs8(q[0], &g00, &y00);
  pairs8(q[1], &g01, &y01);
  pairs8(q[2], &g10, &y10);
  pairs8(q[3], &g11, &y11);
  vd a00 = y00 * fy, a01 = y01 * fy1, a10 = y10 * fy, a11 = y11 * fy1;
  vd gx0 = g00 + v * (g01 - g00), a0 = a00 + v * (a01 - a00);
  vd gx1 = g10 + v * (g11 - g10), a1 = a10 + v * (a11 - a10);
  return v_blend(fx, gx0, a0, gx1, a1);
}

static int points2_q(const nl_noise_grad2 *t, const double *x, const double *y, size_t n,
                     double *out)
{
  size_t m = t->m;
  if (!points2_foldable(t, n))
    return points2(t, x, y, n, out);
  int slow = 0;
  double q2[2 * NL_Q2_MAX];
  unsigned p2[NL_Q2_MAX + 1];
  points2_fold_tables(t, q2, p2);
  __m512i bad = _mm512_set1_epi32((int)0x80000000u);
  for (size_t k = 0; k < n; k += NL_SIMD_W) {
    vd vx = ld(x + k), vy = ld(y + k);
    __m512i c = _mm512_inserti64x4(_mm512_castsi256_si512(cell_ints(vx)), cell_ints(vy), 1);
    if (_mm512_cmpeq_epi32_mask(c, bad)) {   /* no int cell: the scalar code */
      for (size_t l = 0; l < NL_SIMD_W; l++)
        out[k + l] = nl_noise_grad2_eval(t, x[k + l], y[k + l]);
      slow = 1;
      continue;
    }
    st(out + k, points2_q8(p2, q2, (unsigned)(m - 1), vx, vy));
  }
  return slow;
}

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples, columns3_64, points2_q, points3, points3_sum,
                                           points3_bounded, refused_lanes};

#if defined(__clang__)
#pragma clang attribute pop
#endif
