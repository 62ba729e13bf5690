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

/* The batches on level K, each returning 1 if a point went through the
 * scalar code (always on the scalar level), 0 if every point had finite
 * coordinates below 2^31 (times f for a sum): the checked batches' test. */
static int grad2_points(const nl_noise_simd_kernels *K, const nl_noise_grad2 *t, const double *x,
                        const double *y, size_t n, double *out)
{
  if (!K) {
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_grad2_eval(t, x[k], y[k]);
    return 1;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  int slow = nb ? K->points2(t, x, y, nb, out) : 0;
  if (nb == n) return slow;
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, res[NL_SIMD_PAD];
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  slow |= K->points2(t, xs, ys, NL_SIMD_PAD, res);
  memcpy(out + nb, res, (n - nb) * sizeof *res);
  return slow;
}

static int perm3_points(const nl_noise_simd_kernels *K, const nl_noise_perm3 *p, const double *x,
                        const double *y, const double *z, size_t n, double *out)
{
  const int *p32 = K ? perm3_ints(p) : NULL;
  if (!p32) {   /* the scalar level, or not a doubled table: the scalar code indexes all 512 */
    for (size_t k = 0; k < n; k++) out[k] = nl_noise_perm3_eval(p, x[k], y[k], z[k]);
    return 1;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  int slow = nb ? K->points3(p, p32, x, y, z, nb, out) : 0;
  if (nb == n) return slow;
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, zs[NL_SIMD_PAD] = {0}, res[NL_SIMD_PAD];
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  memcpy(zs, z + nb, (n - nb) * sizeof *zs);
  slow |= K->points3(p, p32, xs, ys, zs, NL_SIMD_PAD, res);
  memcpy(out + nb, res, (n - nb) * sizeof *res);
  return slow;
}

static int perm3_points_sum(const nl_noise_simd_kernels *K, const nl_noise_perm3 *p, double f,
                            const double *x, const double *y, const double *z, size_t n,
                            double amp, double *sum, double *top)
{
  const int *p32 = K ? perm3_ints(p) : NULL;
  if (!p32) {   /* the scalar level, or not a doubled table */
    for (size_t k = 0; k < n; k++) {
      double v = nl_noise_perm3_eval(p, f * x[k], f * y[k], f * z[k]), a = fabs(v);
      *top = a > *top ? a : *top;
      sum[k] = sum[k] + amp * v;
    }
    return 1;
  }
  size_t nb = n / NL_SIMD_PAD * NL_SIMD_PAD;
  int slow = nb ? K->points3_sum(p, p32, f, x, y, z, nb, amp, sum, top) : 0;
  if (nb == n) return slow;
  /* the tail through a padded block: noise(0, 0, 0) = 0 leaves top alone */
  double xs[NL_SIMD_PAD] = {0}, ys[NL_SIMD_PAD] = {0}, zs[NL_SIMD_PAD] = {0}, ss[NL_SIMD_PAD] = {0};
  memcpy(xs, x + nb, (n - nb) * sizeof *xs);
  memcpy(ys, y + nb, (n - nb) * sizeof *ys);
  memcpy(zs, z + nb, (n - nb) * sizeof *zs);
  memcpy(ss, sum + nb, (n - nb) * sizeof *ss);
  slow |= K->points3_sum(p, p32, f, xs, ys, zs, NL_SIMD_PAD, amp, ss, top);
  memcpy(sum + nb, ss, (n - nb) * sizeof *ss);
  return slow;
}

void nl_noise_grad2_points(const nl_noise_grad2 *t, const double *x, const double *y, size_t n,
                           double *out)
{
  grad2_points(kernels(), t, x, y, n, out);
}

void nl_noise_perm3_points(const nl_noise_perm3 *p, const double *x, const double *y,
                           const double *z, size_t n, double *out)
{
  perm3_points(kernels(), p, x, y, z, n, out);
}

double nl_noise_perm3_points_sum(const nl_noise_perm3 *p, double f, const double *x,
                                 const double *y, const double *z, size_t n, double amp,
                                 double *sum)
{
  double top = 0.0;
  perm3_points_sum(kernels(), p, f, x, y, z, n, amp, sum, &top);
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

/* ---- checked batches ------------------------------------------------------- */

/* Points per block of a checked batch (NL_NOISE_CHECK_BLOCK): three
 * coordinate blocks and the output stay in L1 (32 KiB) between the kernel
 * and the check. */
#define NL_CHECK_BLOCK NL_NOISE_CHECK_BLOCK

/* Whether f |c| leaves the lattice's range (NaN and infinity do). */
static inline int refused(double c, double f) { return !(f * fabs(c) < 0x1p52); }

/* The largest lim with f |c| < 2^52 whenever |c| < lim (the product
 * rounds monotonically in |c|): the vector test compares without a
 * multiplication, and where it fails the exact test decides. */
static double lattice_lim(double f)
{
  double lim = 0x1p52 / f;
  while (lim > 0 && !(f * lim < 0x1p52)) lim = nextafter(lim, 0.0);
  return lim;
}

/* 1 if some coordinate of the block may be refused: the level's vector
 * test over whole vectors, the scalar one on the tail. */
static int block_refused(const nl_noise_simd_kernels *K, const double *x, const double *y,
                         const double *z, size_t n, double f, double lim)
{
  size_t nb = K ? n / NL_SIMD_PAD * NL_SIMD_PAD : 0;
  if (nb && K->refused(x, y, z, nb, lim)) return 1;
  for (size_t k = nb; k < n; k++)
    if (refused(x[k], f) || refused(y[k], f) || (z && refused(z[k], f))) return 1;
  return 0;
}

/* nl_noise_points_refused with the level and lim (lattice_lim(f)) given. */
static size_t first_refused(const nl_noise_simd_kernels *K, const double *x, const double *y,
                            const double *z, size_t n, double f, double lim)
{
  for (size_t k0 = 0; k0 < n; k0 += NL_CHECK_BLOCK) {
    size_t m = n - k0 < NL_CHECK_BLOCK ? n - k0 : NL_CHECK_BLOCK;
    if (!block_refused(K, x + k0, y + k0, z ? z + k0 : NULL, m, f, lim)) continue;
    for (size_t k = k0; k < k0 + m; k++)
      if (refused(x[k], f) || refused(y[k], f) || (z && refused(z[k], f))) return k;
  }
  return n;
}

size_t nl_noise_points_refused(const double *x, const double *y, const double *z, size_t n,
                               double f)
{
  return first_refused(kernels(), x, y, z, n, f, lattice_lim(f));
}

/* The kernel runs first, writing out, and tells whether every point of
 * the block had finite coordinates below 2^31 (times f for each octave):
 * its vector code tests that anyway, so the check costs nothing then; a
 * block with a point outside is checked exactly. A separate pass over the
 * points (nl_noise_points_refused) cost 1.3x the bare call at 10^6 points
 * when it came first (the points' trip from memory stalls it), 1.07x
 * right after the kernel, on the same block in cache. */
size_t nl_noise_perm3_points_checked(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                                     const double *x, const double *y, const double *z, size_t n,
                                     double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  double f = o ? nl_noise_octaves_fmax(o) : 1.0, lim = lattice_lim(f), top = 0.0;
  for (size_t k0 = 0; k0 < n; k0 += NL_CHECK_BLOCK) {
    size_t m = n - k0 < NL_CHECK_BLOCK ? n - k0 : NL_CHECK_BLOCK;
    const double *xb = x + k0, *yb = y + k0, *zb = z + k0;
    int slow = 0;
    if (!o) {
      slow = perm3_points(K, p, xb, yb, zb, m, out + k0);
    } else {
      memset(out + k0, 0, m * sizeof *out);
      for (int l = 0; l < o->n; l++)
        slow |= perm3_points_sum(K, p, o->freq[l], xb, yb, zb, m, o->amp[l], out + k0, &top);
    }
    size_t ok = slow ? first_refused(K, xb, yb, zb, m, f, lim) : m;
    if (ok < m) return k0 + ok;
  }
  return n;
}

size_t nl_noise_grad2_points_checked(const nl_noise_grad2 *t, const double *x, const double *y,
                                     size_t n, double *out)
{
  const nl_noise_simd_kernels *K = kernels();
  double lim = lattice_lim(1.0);
  for (size_t k0 = 0; k0 < n; k0 += NL_CHECK_BLOCK) {
    size_t m = n - k0 < NL_CHECK_BLOCK ? n - k0 : NL_CHECK_BLOCK;
    int slow = grad2_points(K, t, x + k0, y + k0, m, out + k0);
    size_t ok = slow ? first_refused(K, x + k0, y + k0, NULL, m, 1.0, lim) : m;
    if (ok < m) return k0 + ok;
  }
  return n;
}
