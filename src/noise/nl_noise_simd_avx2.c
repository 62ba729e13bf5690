/* nl_noise_simd_avx2.c - the kernels of nl_noise_simd_body.h for AVX2, 4
 * doubles a vector. Compiled with a target pragma, never -march: called only
 * when the dispatcher has seen the CPU support it. No FMA: see
 * nl_noise_simd.h. */
#include "simd/nl_simd_avx2.h"   /* vd, vl, v_floor, v_ceil, v_all */
#include "noise/nl_noise_simd.h"
#include <string.h>

#define NL_SIMD_W 4
/* Instructions scheduled before register allocation, minding register
 * pressure: with 16 vector registers GCC's default order spills in the
 * batch's arithmetic (3D batch 163-166 against 158-159 Ms/s, in turns).
 * Scheduling moves no floating-point operation across another's operands:
 * the same operations, the same bits. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("schedule-insns", "sched-pressure")
#endif
#define NL_SIMD_TABLE nl_noise_simd_avx2
typedef int vi __attribute__((vector_size(16)));
typedef unsigned vu __attribute__((vector_size(16)));

/* Lookups lane by lane where nothing below replaces them. */
#include "simd/nl_simd_lanes.h"

#include "noise/nl_noise_simd_body.h"
#include <math.h>

/* ---- rows: the sample loop through a window -------------------------------
 *
 * While 4 consecutive samples span at most 3 columns (3 |dx| <= 2 leaves
 * room for the rounding of x), the columns they use are gx[b .. b + 3] for
 * b the lowest of them, and gx[b + 1 .. b + 4] for the right-hand ones:
 * four loads and four cross-lane permutes (vpermps on pairs of 32-bit
 * halves) per 4 samples, where lane by lane takes 16 loads and the
 * shuffles that gather them. The column arrays are padded for the loads
 * past the last column (NL_SIMD_COL_PAD). plain: no x is -0, so v_cell's
 * +0 changes nothing and is left out (as the AVX-512 level). */
static inline __m256 pick(const double *base, __m256i ix)
{
  return _mm256_permutevar8x32_ps(_mm256_loadu_ps((const float *)base), ix);
}
static inline __attribute__((always_inline)) void
samples_win(const double *gx, const double *a, long ifirst, double x0, double dx, size_t n,
            double *out, int mode, double amp, int plain, int rev)
{
  vd kv = {0, 1, 2, 3}, vfirst = SPLAT((double)ifirst);
  const __m256i pair = _mm256_setr_epi32(0, 1, 0, 1, 0, 1, 0, 1);
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    vd x = kv * dx + x0;                  /* x0 + (double)k * dx */
    vd cell = plain ? v_floor(x) : v_cell(x);
    vd c = cell - vfirst;                 /* lfloor(x) - ifirst, exact */
    __m128d lane = _mm256_castpd256_pd128((__m256d)c);
    if (rev) { __m128d q = _mm256_extractf128_pd((__m256d)c, 1); lane = _mm_unpackhi_pd(q, q); }
    long b = _mm_cvttsd_si64(lane);
    /* the lane offsets 0..3 as the dword pairs (2 o, 2 o + 1) of vpermps:
     * o + 2^52 holds o in its low bits, exactly */
    vd off = (c - (vd)_mm256_broadcastsd_pd(lane)) + 0x1p52;
    __m256i o = _mm256_shuffle_epi32((__m256i)off, 0xa0);   /* (o, o) in each qword */
    __m256i ix = _mm256_add_epi32(_mm256_add_epi32(o, o), pair);
    vd g0 = (vd)_mm256_castps_pd(pick(gx + b, ix)), a0 = (vd)_mm256_castps_pd(pick(a + b, ix));
    vd g1 = (vd)_mm256_castps_pd(pick(gx + b + 1, ix)), a1 = (vd)_mm256_castps_pd(pick(a + b + 1, ix));
    vd v = v_blend(v_frac(x, cell), g0, a0, g1, a1);
    st(out + k, v_emit(out + k, v, mode, amp));
  }
  if (k < n) samples_tail(gx, a, ifirst, x0, dx, k, n, out, mode, amp);
}

static void samples(const double *gx, const double *a, long ifirst, double x0, double dx,
                    size_t n, double *out, int mode, double amp)
{
  if (!(fabs(dx) * 3 <= 2)) {   /* (a window of 8 for sparser rows measured no faster) */
    samples_lanes(gx, a, ifirst, x0, dx, n, out, mode, amp);
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

/* ---- 3D points 32 at a time ------------------------------------------------
 *
 * Perlin's hashing of a point (14 lookups of the permutation) runs in the
 * scalar integer pipes, lane by lane, interleaved with the vector
 * arithmetic of the block two before: on AMD Zen 4 the vector pipes are
 * full with the arithmetic, the integer ones idle, and vpgatherdd from the
 * permutation widened to int was slower (3D batch 92 Ms/s against 109 with
 * the same hashing not interleaved). The 8 corner hashes of a point are
 * kept as bytes; their gradients' components (Perlin's 16, each -1, 0 or
 * 1) are one vpshufb per component for 32 hashes, widened to int32 and
 * converted to doubles where the arithmetic reads them (vcvtdq2pd from
 * memory: exact), in place of 24 double loads a point lane by lane. The
 * arithmetic is v_column3_fp's and v_blend's on these doubles, the same
 * operations in the same order. */
/* nl_noise_simd_g3 as int8, for vpshufb */
static const signed char g3b[3][16] __attribute__((aligned(16))) = {
  {1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0},
  {1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1},
  {0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1}};

/* A block of 32 points: fractions, cells & 255 (as ints) and, once
 * hashed, the corner hashes (hb, laid out by hash4) and their gradient
 * components: g[q][c][comp] holds, for the 8 points 8 q .. 8 q + 7 and
 * column i + c, corner e's component at 8 e + l for point 8 q + l, e =
 * 0..3 for h00, h01, h10, h11 of v_column3 (of the x component, e = 2, 3
 * hold h10's less h00's and h11's less h01's: grads32n). */
typedef struct {
  double fr[3][32];
  int ci[3][32];
  unsigned char hb[4][2][32];
  int g[4][2][3][32];
  int ok;
} __attribute__((aligned(32))) block32;

/* The fractions and cells of 32 points (scaled by f if scale); ok = 0 if a
 * coordinate leaves |.| < 2^31 (then the block is not hashed). The
 * fraction is v_perm3's: x - v_cell(x). */
static inline __attribute__((always_inline)) void
cells32(double f, int scale, const double *x, const double *y, const double *z, block32 *B)
{
  const double *src[3] = {x, y, z};
  vl ok = (vl){0} - 1;
  for (int a = 0; a < 3; a++)
    for (int g = 0; g < 8; g++) {
      vd v = ld(src[a] + 4 * g);
      if (scale) v = f * v;   /* f * x[k] ... */
      ok &= v_small(v);
      vd c = v_cell(v);
      st(B->fr[a] + 4 * g, v - c);
      _mm_store_si128((__m128i *)(B->ci[a] + 4 * g),
                      _mm_and_si128(_mm256_cvttpd_epi32((__m256d)c), _mm_set1_epi32(255)));
    }
  B->ok = v_all(ok);
}

/* Points l0 .. l0 + 3 of a block: nl_noise.c column3's hashing for
 * columns i and i + 1 (cells & 255, cells32). The permutation is doubled,
 * so p[X + 1] needs no & 255, and the last lookups read the pairs
 * (p[AA], p[AA + 1]) and (p[AB], p[AB + 1]) of p15, the permutation & 15,
 * as one 16-bit load each, stored as they are: hb[q][c] holds, for point
 * 8 q + l, h00 and h01 at bytes 2 l, 2 l + 1, h10 and h11 at 16 + 2 l,
 * 16 + 2 l + 1 (grads32 reorders them). */
static inline __attribute__((always_inline)) void
hash4(const unsigned char *pp, const unsigned char *p15, block32 *B, int l0)
{
  /* size_t indices and p + 1 as its own pointer: no zero extensions, and
   * A + 1 in the address (7% of the batch's instructions) */
  const unsigned char *pp1 = pp + 1;
#pragma GCC unroll 4
  for (int l = l0; l < l0 + 4; l++) {
    size_t X = (size_t)B->ci[0][l], Y = (size_t)B->ci[1][l], Z = (size_t)B->ci[2][l];
    for (int c = 0; c < 2; c++) {
      size_t A = (c ? pp1 : pp)[X] + Y, AA = pp[A] + Z, AB = pp1[A] + Z;
      unsigned char *h = B->hb[l >> 3][c] + 2 * (l & 7);
      memcpy(h, p15 + AA, 2);
      memcpy(h + 16, p15 + AB, 2);
    }
  }
}

/* The components of a hashed block: one vpshufb of Perlin's table by
 * hash (as int8), widened to int32, which the arithmetic converts to
 * double as it reads them (vcvtdq2pd from memory, one instruction). */
static inline void grads32n(block32 *B, int nc)
{
  const __m256i unpair = _mm256_setr_epi8(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15,
                                          0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15);
  for (int q = 0; q < 4; q++)
    for (int c = 0; c < nc; c++) {
      /* to corners at bytes 8 e + l, e = 0..3 for h00, h01, h10, h11 */
      __m256i h = _mm256_shuffle_epi8(_mm256_load_si256((const __m256i *)B->hb[q][c]), unpair);
      for (int comp = 0; comp < 3; comp++) {
        __m256i t = _mm256_broadcastsi128_si256(_mm_load_si128((const __m128i *)g3b[comp]));
        __m256i v = _mm256_shuffle_epi8(t, h);
        /* x components: h10 - h00 and h11 - h01 in place of h10, h11 (exact
         * in int8), so that column3_b's first lerps skip their subtraction */
        if (comp == 0) v = _mm256_sub_epi8(v, _mm256_permute2x128_si256(v, v, 0x08));
        int *dst = B->g[q][c][comp];
        _mm256_store_si256((__m256i *)dst, _mm256_cvtepi8_epi32(_mm256_castsi256_si128(v)));
        _mm256_store_si256((__m256i *)(dst + 8),
                           _mm256_cvtepi8_epi32(_mm_srli_si128(_mm256_castsi256_si128(v), 8)));
        __m128i u = _mm256_extracti128_si256(v, 1);
        _mm256_store_si256((__m256i *)(dst + 16), _mm256_cvtepi8_epi32(u));
        _mm256_store_si256((__m256i *)(dst + 24), _mm256_cvtepi8_epi32(_mm_srli_si128(u, 8)));
      }
    }
}

static inline void grads32(block32 *B) { grads32n(B, 2); }

/* Component comp of corner e for the 4 points at o of a row. */
static inline vd gcomp(const int row[3][32], int comp, int e, int o)
{
  return (vd)_mm256_cvtepi32_pd(_mm_load_si128((const __m128i *)(row[comp] + 8 * e + o)));
}

/* v_column3_fp on the components of a row (corners h00, h01, h10, h11 at
 * 0, 1, 2, 3). */
static inline __attribute__((always_inline)) void
column3_b(const int row[3][32], int o, vd fy, vd fz, vd v, vd w, vd *gxo, vd *ao)
{
  /* v_lerp(v, g00, g10) = g00 + v * (g10 - g00), the difference stored */
  *gxo = v_lerp(w, gcomp(row, 0, 0, o) + v * gcomp(row, 0, 2, o),
                gcomp(row, 0, 1, o) + v * gcomp(row, 0, 3, o));
  vd fy1 = fy - 1.0, fz1 = fz - 1.0;
  vd y00 = gcomp(row, 1, 0, o) * fy + gcomp(row, 2, 0, o) * fz;
  vd y10 = gcomp(row, 1, 2, o) * fy1 + gcomp(row, 2, 2, o) * fz;
  vd y01 = gcomp(row, 1, 1, o) * fy + gcomp(row, 2, 1, o) * fz1;
  vd y11 = gcomp(row, 1, 3, o) * fy1 + gcomp(row, 2, 3, o) * fz1;
  *ao = v_lerp(w, v_lerp(v, y00, y10), v_lerp(v, y01, y11));
}

/* Points 4 g .. 4 g + 3 of a hashed block: v_perm3's arithmetic. (Fades
 * made in cells32 and stored cost more than making them here: 120 against
 * 127 Ms/s.) */
static inline __attribute__((always_inline)) vd points_arith32(const block32 *B, int g)
{
  vd fy = ld(B->fr[1] + 4 * g), fz = ld(B->fr[2] + 4 * g);
  vd v = v_fade(fy), w = v_fade(fz), g0, a0, g1, a1;
  int q = g >> 1, o = 4 * (g & 1);
  column3_b(B->g[q][0], o, fy, fz, v, w, &g0, &a0);
  column3_b(B->g[q][1], o, fy, fz, v, w, &g1, &a1);
  return v_blend(ld(B->fr[0] + 4 * g), g0, a0, g1, a1);
}

/* The permutation & 15, for hash4. */
static inline void perm15(const unsigned char *pp, unsigned char *p15)
{
  for (int k = 0; k < 512; k += 32)
    _mm256_storeu_si256((__m256i *)(p15 + k),
                        _mm256_and_si256(_mm256_loadu_si256((const __m256i *)(pp + k)),
                                         _mm256_set1_epi8(15)));
}

/* n points 32 at a time, stored or (sum) scaled by f and summed into out
 * as points3_do (which takes the rest and the blocks that leave 2^31).
 * Three blocks in flight: while block j's arithmetic runs, block j + 2 is
 * hashed, 4 points per 4 of block j, and block j + 1's gradients are made
 * from the hashes stored an iteration before (read at once, the 2-byte
 * stores would not forward to the 32-byte loads: a stall per load). The
 * coordinates are prefetched 4 blocks ahead. */
static inline __attribute__((always_inline)) void hash32(const unsigned char *pp, const unsigned char *p15,
                                                         block32 *B)
{
  for (int l = 0; l < 32; l += 4) hash4(pp, p15, B, l);
}
static inline __attribute__((always_inline)) int
points3_32(const nl_noise_perm3 *P, const int *p32, double f, const double *x, const double *y,
           const double *z, size_t n, double *out, double amp, double *top, int sum)
{
  vd vt = SPLAT(0.0);
  size_t nblk = n / 32, k = 0;
  int slow = 0;
  if (nblk) {
    const unsigned char *pp = P->p;
    unsigned char p15[512];
    perm15(pp, p15);
    block32 blk[3];
    for (size_t j = 0; j < 2 && j < nblk; j++) {
      cells32(f, sum, x + 32 * j, y + 32 * j, z + 32 * j, &blk[j]);
      if (blk[j].ok) hash32(pp, p15, &blk[j]);
    }
    if (blk[0].ok) grads32(&blk[0]);
    for (size_t j = 0; j < nblk; j++, k += 32) {
      block32 *B = &blk[j % 3], *B1 = &blk[(j + 1) % 3], *B2 = &blk[(j + 2) % 3];
      if (j + 1 < nblk && B1->ok) grads32(B1);
      int h2 = 0;
      if (j + 2 < nblk) {
        cells32(f, sum, x + k + 64, y + k + 64, z + k + 64, B2);
        h2 = B2->ok;
      }
      if (!B->ok) {
        slow |= points3_do(P, p32, f, x + k, y + k, z + k, 32, out + k, amp, top, sum);
        if (h2) hash32(pp, p15, B2);
        continue;
      }
#pragma GCC unroll 8
      for (int g = 0; g < 8; g++) {
        if (!(g & 1)) {
          __builtin_prefetch(x + k + 128 + 4 * g);
          __builtin_prefetch(y + k + 128 + 4 * g);
          __builtin_prefetch(z + k + 128 + 4 * g);
        }
        v_points_emit(out + k + 4 * g, points_arith32(B, g), sum, amp, &vt);
        if (h2) hash4(pp, p15, B2, 4 * g);
      }
    }
  }
  if (k < n) slow |= points3_do(P, p32, f, x + k, y + k, z + k, n - k, out + k, amp, top, sum);
  if (sum) *top = v_top(vt, *top);
  return slow;
}

static int points3(const nl_noise_perm3 *P, const int *p32, const double *x, const double *y,
                   const double *z, size_t n, double *out)
{
  return points3_32(P, p32, 1.0, x, y, z, n, out, 0.0, NULL, 0);
}

static int points3_sum(const nl_noise_perm3 *P, const int *p32, double f, const double *x,
                       const double *y, const double *z, size_t n, double amp, double *sum,
                       double *top)
{
  return points3_32(P, p32, f, x, y, z, n, sum, amp, top, 1);
}

/* The bounded term 32 at a time: the 32 are read (hashed) before any of
 * them is packed, and a vector is packed as soon as it is summed (its
 * stores reach at most the vector just read). */
static size_t points3_bounded(const nl_noise_perm3 *P, const int *p32, double f, double amp, double r,
                              const nl_noise_pack *pk0, size_t n, int *hi, size_t *nhi, double *top)
{
  nl_noise_pack q = *pk0;   /* a local copy: the stores into the arrays cannot change its pointers */
  const nl_noise_pack *pk = &q;
  p3tab tab = p3_make(P, p32);
  vd vt = SPLAT(0.0);
  size_t k = 0, left = 0;
  unsigned char p15[512];
  perm15(P->p, p15);
  for (; k + 32 <= n; k += 32) {
    block32 B;
    cells32(f, 1, pk->x + k, pk->y + k, pk->z + k, &B);
    if (!B.ok) {
      left = points3_bounded_do(&tab, P, f, amp, r, pk, k, k + 32, left, hi, nhi, &vt);
      continue;
    }
    hash32(P->p, p15, &B);
    grads32(&B);
    for (int g = 0; g < 8; g++) {
      size_t e = k + 4 * (size_t)g;
      vd v = points_arith32(&B, g);
      v_top_raise(&vt, v);
      left = v_pack(pk, e, ld(pk->x + e), ld(pk->y + e), ld(pk->z + e), ld(pk->base + e),
                    ld(pk->sum + e) + amp * v, r, left, hi, nhi);
    }
  }
  if (k < n) left = points3_bounded_do(&tab, P, f, amp, r, pk, k, n, left, hi, nhi, &vt);
  *top = v_top(vt, *top);
  return left;
}

/* ---- a row's columns ---------------------------------------------------------
 *
 * columns3 (nl_noise_simd_body.h) 32 columns at a time with the batches'
 * machinery: the hashing of column xm + c in the scalar pipes (7 lookups,
 * the last two as pairs), the gradient components by vpshufb, then
 * v_column3_fp's arithmetic at the row's fy, fz. Rows with fewer than 32
 * columns keep the body's. */
static void columns3_32(const nl_noise_perm3 *P, const int *p32, unsigned xm, unsigned ym,
                        unsigned zm, double fy, double fz, double v, double w, size_t ncol,
                        double *gxo, double *ao)
{
  if (ncol < 32) {
    columns3(P, p32, xm, ym, zm, fy, fz, v, w, ncol, gxo, ao);
    return;
  }
  const unsigned char *pp = P->p, *pp1 = pp + 1;
  unsigned char p15[512];
  perm15(pp, p15);
  vd vfy = SPLAT(fy), vfz = SPLAT(fz), vv = SPLAT(v), vw = SPLAT(w);
  block32 B;
  for (size_t c0 = 0; c0 < ncol; c0 += 32) {
    size_t m = ncol - c0 < 32 ? ncol - c0 : 32;   /* a multiple of NL_SIMD_PAD */
    for (size_t l = 0; l < m; l++) {   /* nl_noise.c column3's hashing, as hash4 */
      size_t X = (xm + c0 + l) & 255u, A = pp[X] + (size_t)ym, AA = pp[A] + (size_t)zm,
             AB = pp1[A] + (size_t)zm;
      unsigned char *h = B.hb[l >> 3][0] + 2 * (l & 7);
      memcpy(h, p15 + AA, 2);
      memcpy(h + 16, p15 + AB, 2);
    }
    grads32n(&B, 1);
    for (size_t g = 0; g < m / 4; g++) {
      vd gx, a;
      column3_b(B.g[g >> 1][0], 4 * (int)(g & 1), vfy, vfz, vv, vw, &gx, &a);
      st(gxo + c0 + 4 * g, gx);
      st(ao + c0 + 4 * g, a);
    }
  }
}

/* ---- batches of the 2D table noise ----------------------------------------
 *
 * points2_fold (nl_noise_simd_body.h) with its pairs (gx, gy)[P[a]] read
 * by one 16-byte load per corner and lane and split into the two vectors
 * by two unpacks, as the AVX-512 level does, where the body stores and
 * reloads each double. The indices stay scalar work beside the vectors. */
static inline __attribute__((always_inline)) vd pairs4(const double *const q[4], vd *gy)
{
  __m256d A = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(q[0])), _mm_loadu_pd(q[2]), 1);
  __m256d B = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(q[1])), _mm_loadu_pd(q[3]), 1);
  *gy = (vd)_mm256_unpackhi_pd(A, B);
  return (vd)_mm256_unpacklo_pd(A, B);
}

static int points2_q(const nl_noise_grad2 *t, const double *x, const double *y, size_t n,
                     double *out)
{
  if (!points2_foldable(t, n))
    return points2(t, x, y, n, out);
  int slow = 0;
  double q2[2 * NL_Q2_MAX];
  unsigned p2[NL_Q2_MAX + 1];
  size_t mask = t->m - 1;
  points2_fold_tables(t, q2, p2);
  for (size_t k = 0; k < n; k += NL_SIMD_W) {
    vd vx = ld(x + k), vy = ld(y + k);
    if (!v_all(v_small(vx) & v_small(vy))) {
      for (size_t l = 0; l < NL_SIMD_W; l++)
        out[k + l] = nl_noise_grad2_eval(t, x[k + l], y[k + l]);
      slow = 1;
      continue;
    }
    /* nl_noise_grad2_eval: i = lfloor(x), j = lfloor(y), fy = lfrac(y, j), v = fade(fy) */
    vd ci = v_cell(vx), cj = v_cell(vy);
    vd fy = v_frac(vy, cj), v = v_fade(fy), fx = v_frac(vx, ci);
    int is[4], js[4];
    _mm_storeu_si128((__m128i *)is, _mm256_cvttpd_epi32((__m256d)ci));
    _mm_storeu_si128((__m128i *)js, _mm256_cvttpd_epi32((__m256d)cj));
    const double *q[4][4];   /* corners (i + di, j + dj), q = dj + 2 di */
    for (int l = 0; l < 4; l++) {
      const unsigned *pi = p2 + ((size_t)(unsigned)is[l] & mask);
      size_t j = (unsigned)js[l], p0 = pi[0], p1 = pi[1];
      q[0][l] = q2 + 2 * ((p0 + j) & mask);
      q[1][l] = q2 + 2 * ((p0 + j + 1) & mask);
      q[2][l] = q2 + 2 * ((p1 + j) & mask);
      q[3][l] = q2 + 2 * ((p1 + j + 1) & mask);
    }
    /* column2 at i and i + 1, then blend(lfrac(x, i), ...), as points2_fold */
    vd fy1 = fy - 1.0, y00, y01, y10, y11;
    vd g00 = pairs4(q[0], &y00), g01 = pairs4(q[1], &y01);
    vd g10 = pairs4(q[2], &y10), g11 = pairs4(q[3], &y11);
    vd a00 = y00 * fy, a01 = y01 * fy1, a10 = y10 * fy, a11 = y11 * fy1;
    vd gx0 = g00 + v * (g01 - g00), a0 = a00 + v * (a01 - a00);
    vd gx1 = g10 + v * (g11 - g10), a1 = a10 + v * (a11 - a10);
    st(out + k, v_blend(fx, gx0, a0, gx1, a1));
  }
  return slow;
}

const nl_noise_simd_kernels NL_SIMD_TABLE = {samples, columns3_32, points2_q, points3,
                                           points3_sum, points3_bounded, refused_lanes};

#if defined(__clang__)
#pragma clang attribute pop
#endif
