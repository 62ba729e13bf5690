/* nl_noise_simd.c - the noise kernel table of the library's vector level
 * (simd/nl_simd.h: scalar, SSE2, AVX2 or AVX-512), the row drivers
 * nl_noise.c hands its rows to, and the batch point API. The scalar level
 * is nl_noise.c's own code, the reference; every level gives its bits
 * (nl_noise_simd.h).
 *
 * The scalar lattice helpers (nl_noise_lattice.h) and row_columns
 * (nl_noise_simd.h) are nl_noise.c's; test_noise_simd.c holds the two files
 * to the same bits.
 */
#include "noise/nl_noise_simd.h"
#include "noise/nl_noise_lattice.h"
#include "base/nl_base.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Perlin 2002's grad3 (nl_noise.c), one array per component. */
const double nl_noise_simd_g3[3][16] = {
  {1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0},
  {1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1},
  {0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1}};

static const nl_noise_simd_kernels *kernels(void)
{
  switch (nl_simd_get()) {
#if NL_SIMD_X86
  case NL_SIMD_SSE2: return &nl_noise_simd_sse2;
  case NL_SIMD_AVX2: return &nl_noise_simd_avx2;
  case NL_SIMD_AVX512: return &nl_noise_simd_avx512;
#endif
  default: return NULL;
  }
}


/* ---- rows ------------------------------------------------------------------ */

#define NL_SIMD_STACK_COLS 1056   /* doubles; a multiple of NL_SIMD_PAD */
#define NL_SIMD_CHUNK 256         /* points per call of a sparse row */

/* The int copy of a permutation the lookups read, cached per thread (a row
 * of fBm asks once per octave with the same table), and whether its second
 * half repeats the first, as nl_noise_perm3_reference and nl_noise_perm3_seed make it
 * (the kernels index the first 256 entries only). NULL if it does not. */
static const int *perm3_ints(const nl_noise_perm3 *p)
{
  static _Thread_local struct { int valid, doubled; unsigned char p[512]; int p32[512]; } c;
  if (!c.valid || memcmp(c.p, p->p, sizeof c.p) != 0) {
    memcpy(c.p, p->p, sizeof c.p);
    for (int k = 0; k < 512; k++) c.p32[k] = p->p[k];
    c.doubled = memcmp(p->p, p->p + 256, 256) == 0;
    c.valid = 1;
  }
  return c.doubled ? c.p32 : NULL;
}

static int grad2_pow2(const nl_noise_grad2 *t) { return t->m >= 1 && (t->m & (t->m - 1)) == 0 && t->m <= 0x80000000u; }

/* Room for ncol columns (rounded up to NL_SIMD_PAD) and NL_SIMD_COL_PAD
 * zeroed doubles after them: the stack arrays or the heap. */
static double *column_arrays(size_t ncol, double *sgx, double *sa, double **a)
{
  size_t len = (ncol + NL_SIMD_PAD - 1) / NL_SIMD_PAD * NL_SIMD_PAD + NL_SIMD_COL_PAD;
  double *gx = len <= NL_SIMD_STACK_COLS ? sgx : nl_xmalloc(len * sizeof *gx);
  *a = len <= NL_SIMD_STACK_COLS ? sa : nl_xmalloc(len * sizeof **a);
  memset(gx + ncol, 0, (len - ncol) * sizeof *gx);
  memset(*a + ncol, 0, (len - ncol) * sizeof **a);
  return gx;
}

/* nl_noise.c column2 for columns ifirst .. ifirst + ncol - 1 at y: Cheng
 * 2009 eq. 3.1-3.2, corners (i, j) and (i, j + 1) blended along y. Scalar on
 * every level: a 2D table (M = 512 doubles per component) does not fit in
 * registers, and loads one by one beat gathers; a row has few columns. */
static void columns2(const nl_noise_grad2 *t, long ifirst, size_t ncol, double y, double *gx, double *a)
{
  long j = nl_noise_lfloor(y);
  double fy = nl_noise_lfrac(y, j), v = nl_noise_fade(fy);
  if (grad2_pow2(t)) {   /* i mod m as a mask */
    unsigned long mask = t->m - 1, j0 = (unsigned long)j & mask, j1 = (unsigned long)(j + 1) & mask;
    const unsigned *perm = t->perm;
    double fy1 = fy - 1;
    for (size_t c = 0; c < ncol; c++) {
      unsigned long pi = perm[((unsigned long)ifirst + c) & mask];
      size_t k0 = perm[(pi + j0) & mask], k1 = perm[(pi + j1) & mask];
      double a0 = t->gy[k0] * fy, a1 = t->gy[k1] * fy1;
      gx[c] = t->gx[k0] + v * (t->gx[k1] - t->gx[k0]);
      a[c] = a0 + v * (a1 - a0);
    }
  } else {   /* the general (lmod) path */
    for (size_t c = 0; c < ncol; c++) {
      long i = ifirst + (long)c;
      size_t k0 = nl_noise_grad2_index(t, i, j), k1 = nl_noise_grad2_index(t, i, j + 1);
      double a0 = t->gy[k0] * fy, a1 = t->gy[k1] * (fy - 1);
      gx[c] = t->gx[k0] + v * (t->gx[k1] - t->gx[k0]);
      a[c] = a0 + v * (a1 - a0);
    }
  }
}

/* nl_noise.c column3 for columns ifirst .. at (y, z), by the level's kernel. */
static void columns3(const nl_noise_simd_kernels *K, const nl_noise_perm3 *p, const int *p32, long ifirst,
                     size_t ncol, double y, double z, double *gx, double *a)
{
  long j = nl_noise_lfloor(y), k = nl_noise_lfloor(z);
  double fy = nl_noise_lfrac(y, j), fz = nl_noise_lfrac(z, k);
  double v = nl_noise_fade(fy), w = nl_noise_fade(fz);
  K->columns3(p, p32, (unsigned)(ifirst & 255), (unsigned)(j & 255), (unsigned)(k & 255), fy, fz,
              v, w, (ncol + NL_SIMD_PAD - 1) / NL_SIMD_PAD * NL_SIMD_PAD, gx, a);
}

/* One row of either noise into out (mode, amp: see NL_SIMD_STORE); sparse
 * rows (row_columns 0) go point by point through scratch. */
static void row_any(const nl_noise_simd_kernels *K, const nl_noise_grad2 *t, const nl_noise_perm3 *p,
                    const int *p32, double x0, double dx, double y, double z, size_t n,
                    double *out, int mode, double amp)
{
  long ifirst;
  size_t ncol = row_columns(x0, dx, n, &ifirst);
  if (ncol == 0) {   /* out[k] = nl_noise_grad2_eval(t, x0 + k dx, y) (or 3), by batches */
    double xs[NL_SIMD_CHUNK], ys[NL_SIMD_CHUNK], zs[NL_SIMD_CHUNK], v[NL_SIMD_CHUNK];
    for (size_t k0 = 0; k0 < n; k0 += NL_SIMD_CHUNK) {
      size_t m = n - k0 < NL_SIMD_CHUNK ? n - k0 : NL_SIMD_CHUNK;
      for (size_t k = 0; k < m; k++) { xs[k] = x0 + (double)(k0 + k) * dx; ys[k] = y; zs[k] = z; }
      double *dst = mode == NL_SIMD_STORE ? out + k0 : v;
      if (t) nl_noise_grad2_points(t, xs, ys, m, dst);
      else nl_noise_perm3_points(p, xs, ys, zs, m, dst);
      if (mode == NL_SIMD_STORE) continue;
      double *o = out + k0;   /* nl_noise_fractal_row's loops */
      for (size_t k = 0; k < m; k++) {
        double s = mode & NL_SIMD_ABS ? fabs(v[k]) : v[k];
        o[k] = ((mode & 3) == NL_SIMD_FIRST ? 0.0 : o[k]) + amp * s;
      }
    }
    return;
  }
  double sgx[NL_SIMD_STACK_COLS], sa[NL_SIMD_STACK_COLS], *a;
  double *gx = column_arrays(ncol, sgx, sa, &a);
  if (t) columns2(t, ifirst, ncol, y, gx, a);
  else columns3(K, p, p32, ifirst, ncol, y, z, gx, a);
  K->samples(gx, a, ifirst, x0, dx, n, out, mode, amp);
  if (gx != sgx) { free(gx); free(a); }
}

#define NL_SIMD_MAX_N ((size_t)1 << 29)   /* column indices stay ints */

int nl_noise_simd_row2(const nl_noise_grad2 *t, double x0, double dx, double y, size_t n, double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  if (!K || n > NL_SIMD_MAX_N) return GSL_CONTINUE;
  row_any(K, t, NULL, NULL, x0, dx, y, 0, n, out, NL_SIMD_STORE, 1);
  return GSL_SUCCESS;
}

int nl_noise_simd_row3(const nl_noise_perm3 *p, double x0, double dx, double y, double z,
                       size_t n, double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  const int *p32;
  if (!K || n > NL_SIMD_MAX_N || !(p32 = perm3_ints(p))) return GSL_CONTINUE;
  row_any(K, NULL, p, p32, x0, dx, y, z, n, out, NL_SIMD_STORE, 1);
  return GSL_SUCCESS;
}

/* nl_noise_fractal_row (nl_noise.c) with each octave summed as its row is made:
 * the same operations, out = 0, then out = out + amp_l N_l (or |N_l|), one
 * octave after another, without the pass through scratch. */
int nl_noise_simd_fractal_row(const nl_noise_basis *b, const nl_noise_octaves *o, double x0, double dx,
                              double y, double z, size_t n, double *out, double *scratch)
{
  (void)scratch;
  const nl_noise_simd_kernels *K = kernels();
  if (!K || n > NL_SIMD_MAX_N || o->n < 1) return GSL_CONTINUE;
  const nl_noise_grad2 *t = NULL;
  const nl_noise_perm3 *p = NULL;
  const int *p32 = NULL;
  if (b->row == nl_noise_basis_grad2(NULL).row) t = b->ctx;
  else if (b->row == nl_noise_basis_perm3(NULL).row && (p32 = perm3_ints(b->ctx))) p = b->ctx;
  else return GSL_CONTINUE;
  for (int l = 0; l < o->n; l++) {
    double f = o->freq[l];
    int mode = (l == 0 ? NL_SIMD_FIRST : NL_SIMD_ADD) | (o->turbulence ? NL_SIMD_ABS : 0);
    row_any(K, t, p, p32, x0 * f, dx * f, y * f, z * f, n, out, mode, o->amp[l]);
  }
  return GSL_SUCCESS;
}

/* ---- points ---------------------------------------------------------------- */

void nl_noise_grad2_points(const nl_noise_grad2 *t, const double *x, const double *y, size_t n,
                           double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  if (!K) {
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_grad2_eval(t, x[k], y[k]);
    return;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  if (nb) K->points2(t, x, y, nb, out);
  if (nb == n) return;
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, res[NL_SIMD_PAD];
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  K->points2(t, xs, ys, NL_SIMD_PAD, res);
  memcpy(out + nb, res, (n - nb) * sizeof *res);
}

void nl_noise_perm3_points(const nl_noise_perm3 *p, const double *x, const double *y, const double *z,
                           size_t n, double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  if (!K) {
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_perm3_eval(p, x[k], y[k], z[k]);
    return;
  }
  const int *p32 = perm3_ints(p);
  if (!p32) {   /* not a doubled table: the scalar code indexes all 512 */
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_perm3_eval(p, x[k], y[k], z[k]);
    return;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  if (nb) K->points3(p, p32, x, y, z, nb, out);
  if (nb == n) return;
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, zs[NL_SIMD_PAD] = {0}, res[NL_SIMD_PAD];
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  memcpy(zs, z + nb, (n - nb) * sizeof *zs);
  K->points3(p, p32, xs, ys, zs, NL_SIMD_PAD, res);
  memcpy(out + nb, res, (n - nb) * sizeof *res);
}

double nl_noise_perm3_points_sum(const nl_noise_perm3 *p, double f, const double *x, const double *y,
                                 const double *z, size_t n, double amp, double *sum)
{
  const nl_noise_simd_kernels *K = kernels();
  const int *p32 = K ? perm3_ints(p) : NULL;
  double top = 0.0;
  if (!p32) {   /* the scalar level, or not a doubled table */
    for (size_t k = 0; k < n; k++) {
      double v = nl_noise_perm3_eval(p, f * x[k], f * y[k], f * z[k]), a = fabs(v);
      top = a > top ? a : top;
      sum[k] = sum[k] + amp * v;
    }
    return top;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  if (nb) K->points3_sum(p, p32, f, x, y, z, nb, amp, sum, &top);
  if (nb == n) return top;
  /* the tail through a padded block: noise(0, 0, 0) = 0 leaves top alone */
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, zs[NL_SIMD_PAD] = {0}, ss[NL_SIMD_PAD] = {0};
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  memcpy(zs, z + nb, (n - nb) * sizeof *zs);
  memcpy(ss, sum + nb, (n - nb) * sizeof *ss);
  K->points3_sum(p, p32, f, xs, ys, zs, NL_SIMD_PAD, amp, ss, &top);
  memcpy(sum + nb, ss, (n - nb) * sizeof *ss);
  return top;
}

/* eq. 5.4 after the term, for one point with its new sum: 0 undecided, 1
 * decided at 0, 2 at 1 (the kernels' lane test, in the same operations). */
static int bounded_decided(double base, double sum, double r)
{
  double s = base + sum;
  return s + r <= 0.0 ? 1 : s - r >= 1.0 ? 2 : 0;
}

size_t nl_noise_perm3_points_bounded(const nl_noise_perm3 *p, double f, double amp, double r, nl_noise_pack *pk,
                                     int *hi, double *top)
{
  const nl_noise_simd_kernels *K = kernels();
  const int *p32 = K ? perm3_ints(p) : NULL;
  size_t n = pk->n, nhi = 0, left = 0, k0 = 0;
  double t = *top;
  if (p32) {
    k0 = n / NL_SIMD_PAD * NL_SIMD_PAD;
    if (k0) left = K->points3_bounded(p, p32, f, amp, r, pk, k0, hi, &nhi, &t);
  }
  /* the rest (all of it on the scalar level) point by point; a kernel's
   * tail summed through a padded block, as nl_noise_perm3_points_sum */
  double ss[NL_SIMD_PAD] = {0};
  if (p32 && k0 < n) {
    double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, zs[NL_SIMD_PAD] = {0};
    memcpy(xs, pk->x + k0, (n - k0) * sizeof *xs);
    memcpy(ys, pk->y + k0, (n - k0) * sizeof *ys);
    memcpy(zs, pk->z + k0, (n - k0) * sizeof *zs);
    memcpy(ss, pk->sum + k0, (n - k0) * sizeof *ss);
    K->points3_sum(p, p32, f, xs, ys, zs, NL_SIMD_PAD, amp, ss, &t);
  }
  for (size_t k = k0; k < n; k++) {
    double sum;
    if (p32) sum = ss[k - k0];
    else {
      double nz = nl_noise_perm3_eval(p, f * pk->x[k], f * pk->y[k], f * pk->z[k]);
      t = fabs(nz) > t ? fabs(nz) : t;
      sum = pk->sum[k] + amp * nz;
    }
    int d = bounded_decided(pk->base[k], sum, r);
    if (d == 2) hi[nhi++] = pk->id[k];
    if (d) continue;
    pk->x[left] = pk->x[k]; pk->y[left] = pk->y[k]; pk->z[left] = pk->z[k];
    pk->base[left] = pk->base[k]; pk->sum[left] = sum; pk->id[left] = pk->id[k];
    left++;
  }
  pk->n = left;
  *top = t;
  return nhi;
}
