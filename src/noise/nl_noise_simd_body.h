/* nl_noise_simd_body.h - the SIMD noise kernels, written once.
 *
 * Included by nl_noise_simd_{sse2,avx2,avx512}.c after they define, for
 * their instruction set (see nl_noise_simd.h for the contract):
 *   NL_SIMD_W           lanes of double
 *   NL_SIMD_TABLE       the name of the nl_noise_simd_kernels to define
 *   vd, vl, vi, vu      W doubles, W int64 (comparison results), W int32, W uint32
 *   v_floor(vd)         floor, exact for |x| < 2^52, -0 for -0
 *   v_gd(base, vi)      base[idx] for doubles; v_gi(base, vi) for ints
 *   v_all(vl)           all lanes true
 * and, optionally, NL_SIMD_HAVE_TABLES with p3tab, p3_make, p3_get and g3
 * (register-resident tables instead of memory lookups). The including file
 * then defines its nl_noise_simd_kernels from the functions here (or its
 * own sample loop: samples_lanes is the portable one).
 * Each kernel repeats the scalar operations of nl_noise.c lane by lane, in
 * the same order; the comments name the scalar line each step copies.
 */
#include <string.h>

#include "simd/nl_simd_vec.h"   /* ld, st, splat, SPLAT */
#define SPLATU(x) ((vu){0} + (unsigned)(x))

/* fade(t) = t * t * t * (t * (t * 6 - 15) + 10), Perlin 2002's order. */
static inline vd v_fade(vd t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
static inline vd v_lerp(vd t, vd a, vd b) { return a + t * (b - a); }
/* nl_noise.c blend(): the column lines L_c(t) = t GX + A across the cell. */
static inline vd v_blend(vd t, vd gx0, vd a0, vd gx1, vd a1)
{
  vd l = t * gx0 + a0;
  vd r = (t - 1.0) * gx1 + a1;
  return l + v_fade(t) * (r - l);
}
/* lfloor as a double. The scalar code converts the (long) cell back to
 * double, which is never -0: adding +0 turns floor(-0) = -0 into +0, so
 * x - cell keeps the sign the scalar subtraction gives. */
static inline vd v_cell(vd x) { return v_floor(x) + 0.0; }
/* lfrac for finite x with |x| < 2^52: x - cell, in [0, 1] (1 for x in
 * [-2^-54, 0), as the scalar code keeps it). */
static inline vd v_frac(vd x, vd cell) { return x - cell; }
static inline vl v_small(vd x)   /* |x| < 2^31: the cell fits an int; false for NaN */
{
  vd a = (vd)((vl)x & 0x7fffffffffffffffLL);
  return a < 0x1p31;
}

/* ---- rows ---------------------------------------------------------------- */

/* Where a row's values go (nl_noise_simd.h, NL_SIMD_STORE ...): stored, or
 * added into a sum of octaves as nl_noise_fractal_row does it, out = out + amp v
 * (out = 0 + amp v for the first octave; |v| for turbulence). */
static inline vd v_emit(const double *out, vd v, int mode, double amp)
{
  if (mode & NL_SIMD_ABS) v = (vd)((vl)v & 0x7fffffffffffffffLL);   /* fabs */
  if ((mode & 3) == NL_SIMD_STORE) return v;
  return ((mode & 3) == NL_SIMD_FIRST ? SPLAT(0.0) : ld(out)) + amp * v;
}

/* Samples k0 .. n - 1 (fewer than W of them) through a padded block: the
 * spare lanes repeat sample k0, so every lane stays inside the columns. */
static void samples_tail(const double *gx, const double *a, long ifirst, double x0, double dx,
                         size_t k0, size_t n, double *out, int mode, double amp)
{
  double xs[NL_SIMD_W], res[NL_SIMD_W], acc[NL_SIMD_W] = {0};
  for (int l = 0; l < NL_SIMD_W; l++) xs[l] = x0 + (double)(k0 + ((size_t)l < n - k0 ? (size_t)l : 0)) * dx;
  memcpy(acc, out + k0, (n - k0) * sizeof *acc);
  vd x = ld(xs), cell = v_cell(x);
  vi c = __builtin_convertvector(cell - SPLAT((double)ifirst), vi);
  vd v = v_blend(v_frac(x, cell), v_gd(gx, c), v_gd(a, c), v_gd(gx + 1, c), v_gd(a + 1, c));
  st(res, v_emit(acc, v, mode, amp));
  memcpy(out + k0, res, (n - k0) * sizeof *out);
}

static void samples_lanes(const double *gx, const double *a, long ifirst, double x0, double dx,
                          size_t n, double *out, int mode, double amp)
{
  vd kv, vfirst = SPLAT((double)ifirst);
  for (int l = 0; l < NL_SIMD_W; l++) kv[l] = l;
  size_t k = 0;
  for (; k + NL_SIMD_W <= n; k += NL_SIMD_W, kv += (double)NL_SIMD_W) {
    /* x = x0 + (double)k * dx; i = lfloor(x); c = i - ifirst */
    vd x = kv * dx + x0;
    vd cell = v_cell(x);
    vi c = __builtin_convertvector(cell - vfirst, vi);
    vd v = v_blend(v_frac(x, cell), v_gd(gx, c), v_gd(a, c), v_gd(gx + 1, c), v_gd(a + 1, c));
    st(out + k, v_emit(out + k, v, mode, amp));
  }
  if (k < n) samples_tail(gx, a, ifirst, x0, dx, k, n, out, mode, amp);
}

/* Perlin's grad3 components, by table lookup so the products below are the
 * scalar code's products (signed zeros included); and the permutation's
 * lookups. A level may bring its own (register tables: NL_SIMD_HAVE_TABLES). */
#ifndef NL_SIMD_HAVE_TABLES
typedef struct { const int *p; } p3tab;
static inline p3tab p3_make(const nl_noise_perm3 *P, const int *p32) { (void)P; p3tab t = {p32}; return t; }
static inline vi p3_get(const p3tab *t, vi idx) { return v_gi(t->p, idx); }
static inline vd g3(const p3tab *t, int comp, vi h) { (void)t; return v_gd(nl_noise_simd_g3[comp], h); }
#endif

static inline void v_column3_fp(const p3tab *p, vi h00, vi h10, vi h01, vi h11, vd fy, vd fz,
                                vd v, vd w, vd *gxo, vd *ao);

/* nl_noise.c column3 (Perlin 2002's hashing, the x terms separated) for
 * lanes of columns X at fixed Y, Z. */
static inline void v_column3(const p3tab *p, vi X, vi Y, vi Z, vd fy, vd fz, vd v, vd w,
                             vd *gxo, vd *ao)
{
  vi A = p3_get(p, X) + Y, AA = p3_get(p, A) + Z, AB = p3_get(p, A + 1) + Z;
  vi h00 = p3_get(p, AA) & 15, h10 = p3_get(p, AB) & 15, h01 = p3_get(p, AA + 1) & 15,
     h11 = p3_get(p, AB + 1) & 15;
  v_column3_fp(p, h00, h10, h01, h11, fy, fz, v, w, gxo, ao);
}

/* The arithmetic of column3 once the four corner hashes are known. */
static inline void v_column3_fp(const p3tab *p, vi h00, vi h10, vi h01, vi h11, vd fy, vd fz,
                                vd v, vd w, vd *gxo, vd *ao)
{
  *gxo = v_lerp(w, v_lerp(v, g3(p, 0, h00), g3(p, 0, h10)), v_lerp(v, g3(p, 0, h01), g3(p, 0, h11)));
  vd fy1 = fy - 1.0, fz1 = fz - 1.0;
  /* yz_part(h, y, z) = grad3[h][1] * y + grad3[h][2] * z */
  vd y00 = g3(p, 1, h00) * fy + g3(p, 2, h00) * fz, y10 = g3(p, 1, h10) * fy1 + g3(p, 2, h10) * fz;
  vd y01 = g3(p, 1, h01) * fy + g3(p, 2, h01) * fz1, y11 = g3(p, 1, h11) * fy1 + g3(p, 2, h11) * fz1;
  *ao = v_lerp(w, v_lerp(v, y00, y10), v_lerp(v, y01, y11));
}

static __attribute__((unused)) void
columns3(const nl_noise_perm3 *P, const int *p32, unsigned xm, unsigned ym, unsigned zm, double fy,
                     double fz, double v, double w, size_t ncol, double *gxo, double *ao)
{
  vi iota, Y = (vi){0} + (int)ym, Z = (vi){0} + (int)zm;
  for (int l = 0; l < NL_SIMD_W; l++) iota[l] = l;
  vd vfy = SPLAT(fy), vfz = SPLAT(fz), vv = SPLAT(v), vw = SPLAT(w), g, a;
  p3tab tab = p3_make(P, p32);
  for (size_t c = 0; c < ncol; c += NL_SIMD_W) {
    vi X = ((int)xm + (int)(c & 255) + iota) & 255;
    v_column3(&tab, X, Y, Z, vfy, vfz, vv, vw, &g, &a);
    st(gxo + c, g);
    st(ao + c, a);
  }
}

/* ---- points ---------------------------------------------------------------- */

static int points2(const nl_noise_grad2 *t, const double *x, const double *y, size_t n, double *out)
{
  int slow = 0;
  const int *perm = (const int *)t->perm;
  int pow2 = t->m >= 1 && (t->m & (t->m - 1)) == 0 && t->m <= 0x80000000u;
  vu mask = SPLATU(t->m - 1);
  for (size_t k = 0; k < n; k += NL_SIMD_W) {
    vd vx = ld(x + k), vy = ld(y + k);
    if (!v_all(v_small(vx) & v_small(vy))) {
      for (size_t l = 0; l < NL_SIMD_W; l++) out[k + l] = nl_noise_grad2_eval(t, x[k + l], y[k + l]);
      slow = 1;
      continue;
    }
    /* nl_noise_grad2_eval: i = lfloor(x), j = lfloor(y), fy = lfrac(y, j), v = fade(fy) */
    vd ci = v_cell(vx), cj = v_cell(vy);
    vd fy = v_frac(vy, cj), v = v_fade(fy), fx = v_frac(vx, ci);
    vi i = __builtin_convertvector(ci, vi), j = __builtin_convertvector(cj, vi);
    vi k00, k01, k10, k11;   /* nl_noise_grad2_index(i + di, j + dj) */
    if (pow2) {
      vu i0 = (vu)i & mask, i1 = ((vu)i + 1u) & mask, j0 = (vu)j & mask, j1 = ((vu)j + 1u) & mask;
      vu p0 = (vu)v_gi(perm, (vi)i0), p1 = (vu)v_gi(perm, (vi)i1);
      k00 = v_gi(perm, (vi)((p0 + j0) & mask)); k01 = v_gi(perm, (vi)((p0 + j1) & mask));
      k10 = v_gi(perm, (vi)((p1 + j0) & mask)); k11 = v_gi(perm, (vi)((p1 + j1) & mask));
    } else {   /* the general path: lmod, lane by lane */
      for (int l = 0; l < NL_SIMD_W; l++) {
        long il = i[l], jl = j[l];
        k00[l] = (int)nl_noise_grad2_index(t, il, jl); k01[l] = (int)nl_noise_grad2_index(t, il, jl + 1);
        k10[l] = (int)nl_noise_grad2_index(t, il + 1, jl); k11[l] = (int)nl_noise_grad2_index(t, il + 1, jl + 1);
      }
    }
    /* column2 at i and i + 1, then blend(lfrac(x, i), ...) */
    vd fy1 = fy - 1.0;
    vd g00 = v_gd(t->gx, k00), g01 = v_gd(t->gx, k01), g10 = v_gd(t->gx, k10), g11 = v_gd(t->gx, k11);
    vd a00 = v_gd(t->gy, k00) * fy, a01 = v_gd(t->gy, k01) * fy1;
    vd a10 = v_gd(t->gy, k10) * fy, a11 = v_gd(t->gy, k11) * fy1;
    vd gx0 = g00 + v * (g01 - g00), a0 = a00 + v * (a01 - a00);
    vd gx1 = g10 + v * (g11 - g10), a1 = a10 + v * (a11 - a10);
    st(out + k, v_blend(fx, gx0, a0, gx1, a1));
  }
  return slow;
}

/* points2 for a power-of-two table of at most NL_Q2_MAX entries and a
 * batch of at least m points. Lattice point (i, j) uses G[P[(P[i] + j) mod
 * m]]: the composite table (gx, gy)[P[a]], as interleaved pairs, and P with
 * P[0] repeated after its last entry, made per call (2 m loads), turn a
 * point's 14 loads (2 of P, 4 of P again, 8 of gradients) into 2 adjacent
 * ones of P and 4 pairs. The indices are scalar work beside the vector
 * work. (The AVX-512 kernels bring their own, nl_noise_simd_avx512.c.) */
enum { NL_Q2_MAX = 1024 };
static inline int points2_foldable(const nl_noise_grad2 *t, size_t n)
{
  return t->m >= 1 && (t->m & (t->m - 1)) == 0 && t->m <= NL_Q2_MAX && n >= t->m;
}
static inline void points2_fold_tables(const nl_noise_grad2 *t, double *q2, unsigned *p2)
{
  for (size_t a = 0; a < t->m; a++) {
    p2[a] = t->perm[a];
    q2[2 * a] = t->gx[t->perm[a]];
    q2[2 * a + 1] = t->gy[t->perm[a]];
  }
  p2[t->m] = p2[0];   /* P[(i + 1) mod m] beside P[i] for i = m - 1 too */
}

static __attribute__((unused)) int
points2_fold(const nl_noise_grad2 *t, const double *x, const double *y, size_t n, double *out)
{
  if (!points2_foldable(t, n))
    return points2(t, x, y, n, out);
  int slow = 0;
  double q2[2 * NL_Q2_MAX];
  unsigned p2[NL_Q2_MAX + 1], mask = (unsigned)(t->m - 1);
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
    vi i = __builtin_convertvector(ci, vi), j = __builtin_convertvector(cj, vi);
    double g[4][NL_SIMD_W], gy[4][NL_SIMD_W];   /* corners q = dj + 2 di */
    for (int l = 0; l < NL_SIMD_W; l++) {
      const unsigned *pi = p2 + ((unsigned)i[l] & mask);
      unsigned jl = (unsigned)j[l];
      unsigned e[4] = {(pi[0] + jl) & mask, (pi[0] + jl + 1) & mask, (pi[1] + jl) & mask,
                       (pi[1] + jl + 1) & mask};
      for (int q = 0; q < 4; q++) {
        g[q][l] = q2[2 * e[q]];
        gy[q][l] = q2[2 * e[q] + 1];
      }
    }
    /* column2 at i and i + 1, then blend(lfrac(x, i), ...), as points2 */
    vd fy1 = fy - 1.0;
    vd g00 = ld(g[0]), g01 = ld(g[1]), g10 = ld(g[2]), g11 = ld(g[3]);
    vd a00 = ld(gy[0]) * fy, a01 = ld(gy[1]) * fy1, a10 = ld(gy[2]) * fy, a11 = ld(gy[3]) * fy1;
    vd gx0 = g00 + v * (g01 - g00), a0 = a00 + v * (a01 - a00);
    vd gx1 = g10 + v * (g11 - g10), a1 = a10 + v * (a11 - a10);
    st(out + k, v_blend(fx, gx0, a0, gx1, a1));
  }
  return slow;
}

/* One vector of points of nl_noise_perm3_eval. Lanes whose coordinates
 * leave |.| < 2^31 (or are not finite) go through the scalar code, and
 * set *slow. */
static inline __attribute__((always_inline)) vd
v_perm3(const p3tab *tab, const nl_noise_perm3 *P, vd vx, vd vy, vd vz, int *slow)
{
  if (!v_all(v_small(vx) & v_small(vy) & v_small(vz))) {
    double r[NL_SIMD_W];
    *slow = 1;
    for (int l = 0; l < NL_SIMD_W; l++) r[l] = nl_noise_perm3_eval(P, vx[l], vy[l], vz[l]);
    return ld(r);
  }
  /* nl_noise_perm3_eval: cells, fy = lfrac(y, j), fz, v = fade(fy), w = fade(fz) */
  vd ci = v_cell(vx), cj = v_cell(vy), ck = v_cell(vz);
  vd fy = v_frac(vy, cj), fz = v_frac(vz, ck), v = v_fade(fy), w = v_fade(fz);
  vi i = __builtin_convertvector(ci, vi), j = __builtin_convertvector(cj, vi),
     kk = __builtin_convertvector(ck, vi);
  vd g0, a0, g1, a1;
#ifdef NL_SIMD_HAVE_TABLES
  vi Y = j & 255, Z = kk & 255;
  v_column3(tab, i & 255, Y, Z, fy, fz, v, w, &g0, &a0);
  v_column3(tab, (vi)(((vu)i + 1u) & 255u), Y, Z, fy, fz, v, w, &g1, &a1);
#else
  /* Without register tables the hashing is scalar, lane by lane, in one
   * pass (a vector round trip per lookup costs more than the lookups). */
  const unsigned char *pp = P->p;
  vi h[2][4];
  for (int l = 0; l < NL_SIMD_W; l++) {
    int Y = j[l] & 255, Z = kk[l] & 255;
    for (int c = 0; c < 2; c++) {
      int X = (int)(((unsigned)i[l] + (unsigned)c) & 255u);
      int A = pp[X] + Y, AA = pp[A] + Z, AB = pp[A + 1] + Z;
      h[c][0][l] = pp[AA] & 15; h[c][1][l] = pp[AB] & 15;
      h[c][2][l] = pp[AA + 1] & 15; h[c][3][l] = pp[AB + 1] & 15;
    }
  }
  v_column3_fp(tab, h[0][0], h[0][1], h[0][2], h[0][3], fy, fz, v, w, &g0, &a0);
  v_column3_fp(tab, h[1][0], h[1][1], h[1][2], h[1][3], fy, fz, v, w, &g1, &a1);
#endif
  return v_blend(v_frac(vx, ci), g0, a0, g1, a1);
}

/* Where a vector of points goes: out = v (nl_noise_perm3_points), or one
 * octave of a sum, out = out + amp v, with the lanes' largest |v| so far in
 * *top (nl_noise_perm3_points_sum; fabs(v) > top, so NaN never counts). */
static inline void v_top_raise(vd *top, vd v)
{
  vd a = (vd)((vl)v & 0x7fffffffffffffffLL);
  vl up = (vl)(a > *top);
  *top = (vd)((up & (vl)a) | (~up & (vl)*top));
}
static inline __attribute__((always_inline)) void
v_points_emit(double *out, vd v, int sum, double amp, vd *top)
{
  if (!sum) { st(out, v); return; }
  v_top_raise(top, v);
  st(out, ld(out) + amp * v);
}
/* t raised to the largest lane of top. */
static inline double v_top(vd top, double t)
{
  for (int l = 0; l < NL_SIMD_W; l++) t = top[l] > t ? top[l] : t;
  return t;
}

/* n points (a multiple of NL_SIMD_W): stored, or (sum) scaled by f and
 * summed into out, *top raised to the largest |noise|; 1 if a lane went
 * through the scalar code. */
static inline __attribute__((always_inline)) int
points3_do(const nl_noise_perm3 *P, const int *p32, double f, const double *x, const double *y,
           const double *z, size_t n, double *out, double amp, double *top, int sum)
{
  p3tab tab = p3_make(P, p32);
  vd vt = SPLAT(0.0);
  int slow = 0;
  for (size_t k = 0; k < n; k += NL_SIMD_W) {
    vd vx = ld(x + k), vy = ld(y + k), vz = ld(z + k);
    if (sum) { vx = f * vx; vy = f * vy; vz = f * vz; }   /* f * x[k] ... */
    v_points_emit(out + k, v_perm3(&tab, P, vx, vy, vz, &slow), sum, amp, &vt);
  }
  if (sum) *top = v_top(vt, *top);
  return slow;
}

/* (unused where a level brings its own) */
static __attribute__((unused)) int points3_lanes(const nl_noise_perm3 *P, const int *p32,
                                                 const double *x, const double *y, const double *z,
                                                 size_t n, double *out)
{
  return points3_do(P, p32, 1.0, x, y, z, n, out, 0.0, NULL, 0);
}

static __attribute__((unused)) int points3_sum_lanes(const nl_noise_perm3 *P, const int *p32,
                                                     double f, const double *x, const double *y,
                                                     const double *z, size_t n, double amp,
                                                     double *sum, double *top)
{
  return points3_do(P, p32, f, x, y, z, n, sum, amp, top, 1);
}

/* ---- one term of a bounded sum (nl_noise_perm3_points_bounded) ----------- */

/* eq. 5.4 for the vector of points k .. k + W - 1 with their new sums:
 * decided at 1, the id to hi; undecided, moved to position left (<= k, so
 * nothing not yet read is overwritten). Returns the new left. A level may
 * bring its own (NL_SIMD_HAVE_COMPRESS). */
#ifndef NL_SIMD_HAVE_COMPRESS
static inline size_t v_pack(const nl_noise_pack *pk, size_t k, vd x, vd y, vd z, vd b, vd sum, double r,
                            size_t left, int *hi, size_t *nh)
{
  vd s = b + sum;
  vl lo = (vl)(s + r <= 0.0), up = (vl)(s - r >= 1.0);
  int id[NL_SIMD_W];
  memcpy(id, pk->id + k, sizeof id);
  for (int l = 0; l < NL_SIMD_W; l++) {
    if (up[l]) hi[(*nh)++] = id[l];
    if (lo[l] | up[l]) continue;
    pk->x[left] = x[l]; pk->y[left] = y[l]; pk->z[left] = z[l];
    pk->base[left] = b[l]; pk->sum[left] = sum[l]; pk->id[left] = id[l];
    left++;
  }
  return left;
}
#endif

/* Points k0 .. k1 - 1 (whole vectors), packing from left. */
static inline __attribute__((always_inline)) size_t
points3_bounded_do(const p3tab *tab, const nl_noise_perm3 *P, double f, double amp, double r,
                   const nl_noise_pack *pk, size_t k0, size_t k1, size_t left, int *hi, size_t *nh, vd *vt)
{
  for (size_t k = k0; k < k1; k += NL_SIMD_W) {
    vd x = ld(pk->x + k), y = ld(pk->y + k), z = ld(pk->z + k);
    int slow;
    vd v = v_perm3(tab, P, f * x, f * y, f * z, &slow);   /* noise(f x[k], ...) */
    v_top_raise(vt, v);
    left = v_pack(pk, k, x, y, z, ld(pk->base + k), ld(pk->sum + k) + amp * v, r, left, hi, nh);
  }
  return left;
}

static __attribute__((unused)) size_t
points3_bounded_lanes(const nl_noise_perm3 *P, const int *p32, double f, double amp, double r,
                      const nl_noise_pack *pk, size_t n, int *hi, size_t *nhi, double *top)
{
  nl_noise_pack q = *pk;   /* a local copy: the stores into the arrays cannot change its pointers */
  p3tab tab = p3_make(P, p32);
  vd vt = SPLAT(0.0);
  size_t left = points3_bounded_do(&tab, P, f, amp, r, &q, 0, n, 0, hi, nhi, &vt);
  *top = v_top(vt, *top);
  return left;
}

/* ---- the refusal test of checked batches (nl_noise_points_refused) -------- */

/* All lanes set where |c| < lim (NaN compares false, so it fails). */
static inline vl v_below(const double *c, vd lim)
{
  vd a = (vd)((vl)ld(c) & 0x7fffffffffffffffLL);
  return (vl)(a < lim);
}
static __attribute__((unused)) int refused_lanes(const double *x, const double *y, const double *z,
                                                 size_t n, double lim)
{
  vd vlim = SPLAT(lim);
  if (z) {
    for (size_t k = 0; k < n; k += NL_SIMD_W)
      if (!v_all(v_below(x + k, vlim) & v_below(y + k, vlim) & v_below(z + k, vlim))) return 1;
  } else {
    for (size_t k = 0; k < n; k += NL_SIMD_W)
      if (!v_all(v_below(x + k, vlim) & v_below(y + k, vlim))) return 1;
  }
  return 0;
}
