#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include "simd/nl_simd.h"
#include "noise/nl_noise_lattice.h"   /* nl_noise_lfloor: the cube of a point, for every double */

#include <ctype.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>


/* ---- tables ------------------------------------------------------------ */

nl_status nl_cellular_alloc(double lambda, int M, nl_cellular_count_rule rule, unsigned long seed,
                            nl_cellular **out, nl_error *err)
{
  *out = NULL;
  if (!(lambda > 0.0 && lambda <= 1000.0))
    return nl_fail(err, NL_EINVAL, "cellular: lambda must be in (0, 1000], got %g", lambda);
  if (M < 1 || M > NL_CELLULAR_MAX_M)
    return nl_fail(err, NL_EINVAL, "cellular: M must be in 1..%d, got %d", NL_CELLULAR_MAX_M, M);
  if (rule != NL_COUNT_CLOSEST && rule != NL_COUNT_INVERSE_CDF && rule != NL_COUNT_CLOSEST_LAST)
    return nl_fail(err, NL_EINVAL, "cellular: unknown count rule %d", (int)rule);
  nl_cellular *c = nl_xcalloc(1, sizeof *c);
  c->lambda = lambda;
  c->M = M;
  c->rule = rule;
  /* eq. 3 in log form: lambda^m / m! overflows long before M = 64 would. */
  double acc = 0.0;
  for (int m = 0; m <= M; m++) {
    c->pmf[m] = exp(m * log(lambda) - lambda - nl_lgamma(m + 1.0));
    acc += c->pmf[m];
    c->cdf[m] = acc;
  }
  /* Step 1 of sec. 3.2.2: a table of 2^16 values in 0..2^16-1; we take a
   * permutation so that every seed s is equally likely. */
  c->perm = nl_xmalloc(NL_CELLULAR_PERM * sizeof *c->perm);
  for (unsigned k = 0; k < NL_CELLULAR_PERM; k++) c->perm[k] = (unsigned short)k;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "cellular.perm", 0));
  gsl_ran_shuffle(r, c->perm, NL_CELLULAR_PERM, sizeof *c->perm);
  gsl_rng_free(r);
  *out = c;
  return NL_OK;
}

void nl_cellular_free(nl_cellular *c)
{
  if (!c) return;
  free(c->perm);
  free(c);
}

const char *nl_cellular_count_rule_name(nl_cellular_count_rule rule)
{
  return rule == NL_COUNT_CLOSEST ? "closest" : rule == NL_COUNT_INVERSE_CDF ? "inverse-cdf" : "closest-last";
}

int nl_cellular_count_from_r(const nl_cellular *c, double r)
{
  if (c->rule == NL_COUNT_INVERSE_CDF) {
    for (int m = 0; m <= c->M; m++)
      if (r < c->cdf[m]) return m;
    return c->M;
  }
  /* The paper's rule, literally: argmin_m |p(m) - r|; the paper does not
   * say which m wins a tie, so both are offered (nl_cellular.h). */
  int best = 0, last = c->rule == NL_COUNT_CLOSEST_LAST;
  for (int m = 1; m <= c->M; m++) {
    double d = fabs(c->pmf[m] - r), b = fabs(c->pmf[best] - r);
    if (d < b || (last && d == b)) best = m;
  }
  return best;
}

/* ---- per-cube generator ------------------------------------------------ */

/* splitmix64 (Steele, Lea & Flood 2014): a fast generator that is fine
 * from any seed, including the small integers s < 2^16 used here. */
static inline uint64_t splitmix(uint64_t *state)
{
  uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static inline double uniform01(uint64_t *state) { return (double)(splitmix(state) >> 11) * 0x1.0p-53; }

/* Step 3 (1)-(5): s = PERM(x1 + PERM(x2 + PERM(x3))). */
static inline unsigned cube_seed(const nl_cellular *c, long i, long j, long k)
{
  const unsigned long mask = NL_CELLULAR_PERM - 1;
  unsigned long s = c->perm[(unsigned long)k & mask];
  s = c->perm[((unsigned long)j + s) & mask];
  return c->perm[((unsigned long)i + s) & mask];
}

int nl_cellular_cube(const nl_cellular *c, long i, long j, long k, double *xyz)
{
  uint64_t st = cube_seed(c, i, j, k);
  int m = nl_cellular_count_from_r(c, uniform01(&st));
  for (int q = 0; q < m; q++) {
    xyz[3 * q] = (double)i + uniform01(&st);
    xyz[3 * q + 1] = (double)j + uniform01(&st);
    xyz[3 * q + 2] = (double)k + uniform01(&st);
  }
  return m;
}

/* ---- F1..Fn ------------------------------------------------------------ */

/* Keeps d2[0..n-1] as the n smallest squared distances, ascending. */
static inline void insert_d2(double *d2, int n, double v)
{
  if (v >= d2[n - 1]) return;
  int q = n - 1;
  while (q > 0 && d2[q - 1] > v) { d2[q] = d2[q - 1]; q--; }
  d2[q] = v;
}

static void scan_points(const double *pts, int m, double x, double y, double z, int n, double *d2)
{
  for (int q = 0; q < m; q++) {
    double ax = pts[3 * q] - x, ay = pts[3 * q + 1] - y, az = pts[3 * q + 2] - z;
    insert_d2(d2, n, ax * ax + ay * ay + az * az);
  }
}

static void finish(const double *d2, int n, double *F)
{
  for (int q = 0; q < n; q++)
    F[q] = d2[q] < NL_CELLULAR_FMAX * NL_CELLULAR_FMAX ? sqrt(d2[q]) : NL_CELLULAR_FMAX;
}

static void reset_d2(double *d2, int n)
{
  for (int q = 0; q < n; q++) d2[q] = INFINITY;
}

/* Visit order of the 27 neighbours (nl_cellular_simd.h): codes 9 cx + 3 cy
 * + cz, classes 0 own, 1 near, 2 far, by increasing bound for faces at 1/4
 * (near) and 3/4 (far). */
const unsigned char nl_cellular_visit[27] = {
  0,  9, 3, 1,  12, 10, 4,  13,  18, 6, 2,  21, 19, 15, 7, 11, 5,  22, 16, 14,  24, 20, 8,
  25, 23, 17,  26};

/* Along one axis at coordinate v in cell i (|v| < 2^52): the offset of
 * class 0, 1, 2 (own, near, far) and its squared face distance. */
static void axis_classes(double v, long i, long off[3], double b2[3])
{
  double lo = v - (double)i, hi = (double)(i + 1) - v;
  int near_lo = lo <= hi;
  off[0] = 0;
  off[1] = near_lo ? -1 : 1;
  off[2] = -off[1];
  b2[0] = 0.0;
  b2[1] = near_lo ? lo * lo : hi * hi;
  b2[2] = near_lo ? hi * hi : lo * lo;
}

void nl_cellular_eval(const nl_cellular *c, const double *xyz, int n, double *F)
{
  double pts[3 * NL_CELLULAR_MAX_M], d2[NL_CELLULAR_NMAX];
  long i = nl_noise_lfloor(xyz[0]), j = nl_noise_lfloor(xyz[1]), k = nl_noise_lfloor(xyz[2]);
  reset_d2(d2, n);
  if (!(fabs(xyz[0]) < 0x1p52 && fabs(xyz[1]) < 0x1p52 && fabs(xyz[2]) < 0x1p52)) {
    /* Steps 2-6: the cube around x and its 26 neighbours, all of them. */
    for (long di = -1; di <= 1; di++)
      for (long dj = -1; dj <= 1; dj++)
        for (long dk = -1; dk <= 1; dk++) {
          int m = nl_cellular_cube(c, i + di, j + dj, k + dk, pts);
          scan_points(pts, m, xyz[0], xyz[1], xyz[2], n, d2);
        }
    finish(d2, n, F);
    return;
  }
  /* The same 27 cubes, nearest first, each generated only if one of its
   * points could enter F1..Fn (nl_cellular_simd.h: the same bits). */
  long off[3][3];
  double b2[3][3];
  axis_classes(xyz[0], i, off[0], b2[0]);
  axis_classes(xyz[1], j, off[1], b2[1]);
  axis_classes(xyz[2], k, off[2], b2[2]);
  for (int t = 0; t < 27; t++) {
    int cx = nl_cellular_visit[t] / 9, cy = nl_cellular_visit[t] / 3 % 3, cz = nl_cellular_visit[t] % 3;
    if ((b2[0][cx] + b2[1][cy]) + b2[2][cz] >= d2[n - 1]) continue;
    int m = nl_cellular_cube(c, i + off[0][cx], j + off[1][cy], k + off[2][cz], pts);
    scan_points(pts, m, xyz[0], xyz[1], xyz[2], n, d2);
  }
  finish(d2, n, F);
}

/* A row at fixed (y, z) touches the columns of cubes ifirst..ifirst+ncol-1;
 * column col holds its 9 cubes (rows j-1..j+1, planes k-1..k+1) by class
 * (nl_cellular_rowpts), so each cube is generated once per row, not once per
 * sample. */
typedef struct {
  nl_cellular_rowpts r;
  size_t *start;
  double *px, *ay2, *az2;
} rowbuf;

static void rowbuf_fill(const nl_cellular *c, long ifirst, size_t ncol, double y, double z, rowbuf *b)
{
  long j = nl_noise_lfloor(y), k = nl_noise_lfloor(z), offy[3], offz[3];
  b->r.ifirst = ifirst;
  b->r.ncol = ncol;
  axis_classes(y, j, offy, b->r.by2);
  axis_classes(z, k, offz, b->r.bz2);
  size_t cap = ncol * 9 * 8, total = 0;
  b->px = nl_xmalloc(cap * sizeof *b->px);
  b->ay2 = nl_xmalloc(cap * sizeof *b->ay2);
  b->az2 = nl_xmalloc(cap * sizeof *b->az2);
  b->start = nl_xmalloc((9 * ncol + 1) * sizeof *b->start);
  double tmp[3 * NL_CELLULAR_MAX_M];
  for (size_t col = 0; col < ncol; col++)
    for (int q = 0; q < 9; q++) {
      b->start[9 * col + (size_t)q] = total;
      int m = nl_cellular_cube(c, ifirst + (long)col, j + offy[q / 3], k + offz[q % 3], tmp);
      if (total + (size_t)m > cap) {
        cap = 2 * (total + (size_t)m);
        b->px = nl_xrealloc(b->px, cap * sizeof *b->px);
        b->ay2 = nl_xrealloc(b->ay2, cap * sizeof *b->ay2);
        b->az2 = nl_xrealloc(b->az2, cap * sizeof *b->az2);
      }
      for (int p = 0; p < m; p++) {   /* scan_points' operations */
        double ay = tmp[3 * p + 1] - y, az = tmp[3 * p + 2] - z;
        b->px[total] = tmp[3 * p];
        b->ay2[total] = ay * ay;
        b->az2[total] = az * az;
        total++;
      }
    }
  b->start[9 * ncol] = total;
  b->r.start = b->start;
  b->r.px = b->px;
  b->r.ay2 = b->ay2;
  b->r.az2 = b->az2;
}

static void rowbuf_free(rowbuf *b)
{
  free(b->px); free(b->ay2); free(b->az2); free(b->start);
}

/* The scalar kernel (the reference level): per sample, the 27 cubes of
 * nl_cellular_eval in its visit order, with the same rejection. */
static void row_scalar(const nl_cellular_rowpts *R, double x0, double dx, size_t count, int n, double *F)
{
  double d2[NL_CELLULAR_NMAX], bx2[3];
  long offx[3];
  for (size_t s = 0; s < count; s++) {
    double x = x0 + (double)s * dx;
    long i = nl_noise_lfloor(x);
    size_t col = (size_t)(i - R->ifirst);   /* >= 1: ifirst has a margin */
    axis_classes(x, i, offx, bx2);
    reset_d2(d2, n);
    for (int t = 0; t < 27; t++) {
      int cx = nl_cellular_visit[t] / 9, cy = nl_cellular_visit[t] / 3 % 3, cz = nl_cellular_visit[t] % 3;
      if ((bx2[cx] + R->by2[cy]) + R->bz2[cz] >= d2[n - 1]) continue;
      size_t cube = 9 * (size_t)((long)col + offx[cx]) + (size_t)(3 * cy + cz);
      for (size_t p = R->start[cube]; p < R->start[cube + 1]; p++) {
        double ax = R->px[p] - x;
        insert_d2(d2, n, ax * ax + R->ay2[p] + R->az2[p]);
      }
    }
    finish(d2, n, F + s * (size_t)n);
  }
}

void nl_cellular_row(const nl_cellular *c, double x0, double dx, double y, double z,
                     size_t count, int n, double *F)
{
  if (count == 0) return;
  double xl = x0 + (double)(count - 1) * dx;
  long ifirst = 0, ilast = 0;
  int pointwise = !(fabs(x0) < 0x1p52 && fabs(xl) < 0x1p52 && fabs(y) < 0x1p52 && fabs(z) < 0x1p52);
  if (!pointwise) {   /* a sparse row: buckets would cost more */
    ifirst = nl_noise_lfloor(fmin(x0, xl)) - 1;
    ilast = nl_noise_lfloor(fmax(x0, xl)) + 1;
    pointwise = (size_t)(ilast - ifirst + 1) > 2 * count + 8;
  }
  if (pointwise) {   /* also: no fractional cells, NaN or inf (the full scan) */
    for (size_t s = 0; s < count; s++) {
      double p[3] = {x0 + (double)s * dx, y, z};
      nl_cellular_eval(c, p, n, F + s * (size_t)n);
    }
    return;
  }
  rowbuf b;
  rowbuf_fill(c, ifirst, (size_t)(ilast - ifirst + 1), y, z, &b);
  switch (nl_simd_get()) {   /* the library's level: NL_NOISE_SIMD, nl_simd_set */
#if NL_SIMD_X86
  case NL_SIMD_SSE2: nl_cellular_row_sse2(&b.r, x0, dx, count, n, F); break;
  case NL_SIMD_AVX2: nl_cellular_row_avx2(&b.r, x0, dx, count, n, F); break;
  case NL_SIMD_AVX512: nl_cellular_row_avx512(&b.r, x0, dx, count, n, F); break;
#endif
  default: row_scalar(&b.r, x0, dx, count, n, F);
  }
  rowbuf_free(&b);
}

/* ---- GCTBF ------------------------------------------------------------- */

nl_status nl_cellular_gctbf_add(nl_cellular_gctbf *g, int i, int j, double v, nl_error *err)
{
  if (i < 1 || i > NL_CELLULAR_NMAX || j < 0 || j > NL_CELLULAR_NMAX)
    return nl_fail(err, NL_EINVAL, "gctbf: F index must be in 1..%d", NL_CELLULAR_NMAX);
  if (!isfinite(v)) return nl_fail(err, NL_EINVAL, "gctbf: coefficient is not finite");
  if (j == 0) g->c[i - 1] += v;
  else g->cc[i - 1][j - 1] += v;
  int hi = i > j ? i : j;
  if (hi > g->n) g->n = hi;
  return NL_OK;
}

static const char *skip_ws(const char *s) { while (isspace((unsigned char)*s)) s++; return s; }

/* factor := 'F' digit; returns the index or 0 (s unchanged). */
static int parse_factor(const char **s)
{
  const char *p = skip_ws(*s);
  if (*p == '*') p = skip_ws(p + 1);
  if ((*p != 'F' && *p != 'f') || !isdigit((unsigned char)p[1])) return 0;
  *s = p + 2;
  return p[1] - '0';
}

/* term := [number] factor [factor], sign already consumed. */
static nl_status parse_term(const char **s, double sign, nl_cellular_gctbf *g, const char *expr,
                            nl_error *err)
{
  const char *p = skip_ws(*s);
  double coef = 1.0;
  if (*p != 'F' && *p != 'f') {
    char *end;
    coef = strtod(p, &end);
    if (end == p || !isfinite(coef))
      return nl_fail(err, NL_EINVAL, "gctbf '%s': expected a number or F1..F4 at '%s'", expr, p);
    p = end;
  }
  int i = parse_factor(&p);
  if (!i) return nl_fail(err, NL_EINVAL, "gctbf '%s': expected F1..F4 at '%s'", expr, skip_ws(p));
  int j = parse_factor(&p);
  if (i > NL_CELLULAR_NMAX || j > NL_CELLULAR_NMAX)
    return nl_fail(err, NL_EINVAL, "gctbf '%s': F index must be in 1..%d", expr, NL_CELLULAR_NMAX);
  *s = p;
  return nl_cellular_gctbf_add(g, i, j, sign * coef, err);
}

nl_status nl_cellular_gctbf_parse(const char *expr, nl_cellular_gctbf *g, nl_error *err)
{
  memset(g, 0, sizeof *g);
  const char *p = skip_ws(expr);
  if (!*p) return nl_fail(err, NL_EINVAL, "gctbf: empty expression");
  int first = 1;
  while (*p) {
    double sign = 1.0;
    if (*p == '+' || *p == '-') { sign = *p == '-' ? -1.0 : 1.0; p++; }
    else if (!first) return nl_fail(err, NL_EINVAL, "gctbf '%s': expected + or - at '%s'", expr, p);
    nl_status rc = parse_term(&p, sign, g, expr, err);
    if (rc) { memset(g, 0, sizeof *g); return rc; }
    p = skip_ws(p);
    first = 0;
  }
  return NL_OK;
}

static void append_term(char *buf, size_t len, double v, const char *factors)
{
  size_t used = strlen(buf);
  if (used >= len) return;
  const char *sign = v < 0 ? (used ? " - " : "-") : (used ? " + " : "");
  double a = fabs(v);
  if (a == 1.0) snprintf(buf + used, len - used, "%s%s", sign, factors);
  else snprintf(buf + used, len - used, "%s%g%s", sign, a, factors);
}

void nl_cellular_gctbf_format(const nl_cellular_gctbf *g, char *buf, size_t len)
{
  if (!len) return;
  buf[0] = '\0';
  char f[8];
  for (int i = 0; i < NL_CELLULAR_NMAX; i++)
    if (g->c[i] != 0.0) { snprintf(f, sizeof f, "F%d", i + 1); append_term(buf, len, g->c[i], f); }
  for (int i = 0; i < NL_CELLULAR_NMAX; i++)
    for (int j = 0; j < NL_CELLULAR_NMAX; j++)
      if (g->cc[i][j] != 0.0) {
        snprintf(f, sizeof f, "F%dF%d", i + 1, j + 1);
        append_term(buf, len, g->cc[i][j], f);
      }
  if (!buf[0]) snprintf(buf, len, "0");
}

double nl_cellular_gctbf_value(const nl_cellular_gctbf *g, const double *F)
{
  double v = 0.0;
  for (int i = 0; i < g->n; i++) {
    v += g->c[i] * F[i];
    for (int j = 0; j < g->n; j++) v += g->cc[i][j] * F[i] * F[j];
  }
  return v;
}

double nl_cellular_gctbf_bound(const nl_cellular_gctbf *g)
{
  double b = 0.0;
  for (int i = 0; i < NL_CELLULAR_NMAX; i++) {
    b += fabs(g->c[i]) * NL_CELLULAR_FMAX;
    for (int j = 0; j < NL_CELLULAR_NMAX; j++) b += fabs(g->cc[i][j]) * NL_CELLULAR_FMAX * NL_CELLULAR_FMAX;
  }
  return b;
}

void nl_cellular_gctbf_row(const nl_cellular *c, const nl_cellular_gctbf *g, double x0, double dx, double y,
                           double z, size_t count, double *out)
{
  int n = g->n > 0 ? g->n : 1;
  double *F = nl_xmalloc(count * (size_t)n * sizeof *F);
  nl_cellular_row(c, x0, dx, y, z, count, n, F);
  for (size_t s = 0; s < count; s++) out[s] = g->n ? nl_cellular_gctbf_value(g, F + s * (size_t)n) : 0.0;
  free(F);
}

void nl_cellular_points(const nl_cellular *c, const double *x, const double *y, const double *z,
                        size_t count, int n, double *F)
{
  for (size_t k = 0; k < count; k++) {
    double p[3] = {x[k], y[k], z[k]};
    nl_cellular_eval(c, p, n, F + k * (size_t)n);
  }
}

void nl_cellular_gctbf_points(const nl_cellular *c, const nl_cellular_gctbf *g, const double *x,
                              const double *y, const double *z, size_t count, double *out)
{
  int n = g->n > 0 ? g->n : 1;
  for (size_t k = 0; k < count; k++) {
    double p[3] = {x[k], y[k], z[k]}, F[NL_CELLULAR_NMAX];
    nl_cellular_eval(c, p, n, F);
    out[k] = g->n ? nl_cellular_gctbf_value(g, F) : 0.0;
  }
}

void nl_cellular_gctbf_grid(const nl_cellular *c, const nl_cellular_gctbf *g, const nl_noise_window *win, double *out)
{
  double dx = win->size / win->w, dy = win->size / win->h;
  for (int r = 0; r < win->h; r++)
    nl_cellular_gctbf_row(c, g, win->x0 + 0.5 * dx, dx, win->y0 + (r + 0.5) * dy, win->z, (size_t)win->w,
                          out + (size_t)r * win->w);
}

static void gctbf_basis_row(const void *ctx, double x0, double dx, double y, double z, size_t n,
                            double *out)
{
  const nl_cellular_gctbf_basis *b = ctx;
  nl_cellular_gctbf_row(b->cell, &b->g, x0, dx, y, z, n, out);
}

nl_noise_basis nl_cellular_basis_gctbf(const nl_cellular_gctbf_basis *ctx)
{
  nl_noise_basis b = {gctbf_basis_row, ctx, nl_cellular_gctbf_bound(&ctx->g)};
  return b;
}

/* ---- count statistics -------------------------------------------------- */

void nl_cellular_count_histogram(const nl_cellular *c, long origin, int side, double *hist)
{
  for (int m = 0; m <= c->M; m++) hist[m] = 0.0;
  for (long i = origin; i < origin + side; i++)
    for (long j = origin; j < origin + side; j++)
      for (long k = origin; k < origin + side; k++) {
        uint64_t st = cube_seed(c, i, j, k);
        hist[nl_cellular_count_from_r(c, uniform01(&st))] += 1.0;
      }
}

nl_status nl_cellular_count_chisq(const nl_cellular *c, const double *hist,
                                  nl_stats_chisq_result *res, nl_error *err)
{
  double n = 0.0;
  for (int m = 0; m <= c->M; m++) n += hist[m];
  /* Bins 0..K-1 exact, bin K pools m >= K against the Poisson tail
   * 1 - P(K-1) (not the truncated table: the test is against Poisson). */
  int K = 0;
  while (K < c->M && n * c->pmf[K] >= 5.0 && n * (1.0 - c->cdf[K]) >= 5.0) K++;
  if (K < 1) return nl_fail(err, NL_EINVAL, "cellular chi-square: too few cubes (%g)", n);
  double obs[NL_CELLULAR_MAX_M + 1], exp_[NL_CELLULAR_MAX_M + 1];
  for (int m = 0; m < K; m++) { obs[m] = hist[m]; exp_[m] = n * c->pmf[m]; }
  obs[K] = 0.0;
  for (int m = K; m <= c->M; m++) obs[K] += hist[m];
  exp_[K] = n * (1.0 - c->cdf[K - 1]);
  return nl_stats_chisq_test(obs, exp_, (size_t)K + 1, res, err);
}

double nl_cellular_f1_cdf(double r, void *params)
{
  double lambda = *(const double *)params;
  return r <= 0.0 ? 0.0 : -expm1(-lambda * 4.0 / 3.0 * NL_PI * r * r * r);
}

nl_status nl_cellular_f1_ks(const nl_cellular *c, size_t n, unsigned long seed,
                            nl_stats_ks_result *res, double *mean_f1, nl_error *err)
{
  if (n < 1) return nl_fail(err, NL_EINVAL, "cellular KS: need at least one point");
  double *f1 = nl_xmalloc(n * sizeof *f1), sum = 0.0, lambda = c->lambda;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "cellular.ks_points", 0));
  for (size_t s = 0; s < n; s++) {
    double p[3];
    for (int a = 0; a < 3; a++) p[a] = 1000.0 * gsl_rng_uniform(r);
    nl_cellular_eval(c, p, 1, f1 + s);
    sum += f1[s];
  }
  gsl_rng_free(r);
  if (mean_f1) *mean_f1 = sum / (double)n;
  nl_status rc = nl_stats_ks_test(f1, n, nl_cellular_f1_cdf, &lambda, res, err);
  free(f1);
  return rc;
}

/* ---- texturing --------------------------------------------------------- */

/* Sum over octaves i = 0..octaves of w_i(GCTBF(2^i k x)), row by row. */
typedef double (*octave_term)(double g, int i);

static double bump_term(double g, int i) { return fabs(0.5 - g) / ldexp(1.0, i); }
static double cloud_term(double g, int i) { return (1.0 - 2.0 * g) / ldexp(1.0, i); }

static void octave_grid(const nl_cellular_gctbf_basis *b, int octaves, double k, const nl_noise_window *win,
                        octave_term term, double *out)
{
  double dx = win->size / win->w, dy = win->size / win->h;
  double *g = nl_xmalloc((size_t)win->w * sizeof *g);
  for (size_t s = 0; s < (size_t)win->w * win->h; s++) out[s] = 0.0;
  for (int i = 0; i <= octaves; i++) {
    double f = k * ldexp(1.0, i);
    for (int r = 0; r < win->h; r++) {
      double *o = out + (size_t)r * win->w;
      nl_cellular_gctbf_row(b->cell, &b->g, f * (win->x0 + 0.5 * dx), f * dx,
                            f * (win->y0 + (r + 0.5) * dy), f * win->z, (size_t)win->w, g);
      for (int s = 0; s < win->w; s++) o[s] += term(g[s], i);
    }
  }
  free(g);
}

void nl_cellular_gctbf_fractal_bump_grid(const nl_cellular_gctbf_basis *b, int octaves, double k,
                                         const nl_noise_window *win, double *out)
{
  octave_grid(b, octaves, k, win, bump_term, out);
  /* eq. 6: bump = fractal^3 */
  for (size_t s = 0; s < (size_t)win->w * win->h; s++) out[s] = out[s] * out[s] * out[s];
}

/* eq. 7's smoothscale(p) is RenderMan's antialiasing fade (Ebert ch. 10-13),
 * which depends on the shading footprint; on our rasters the octaves stay
 * well below the pixel rate, so it is 1 here. */
void nl_cellular_gctbf_cloud_grid(const nl_cellular_gctbf_basis *b, int octaves, double k,
                                  const nl_noise_window *win, double *out)
{
  octave_grid(b, octaves, k, win, cloud_term, out);
}

nl_status nl_cellular_texture_grid(nl_cellular_gctbf_texture kind, const char *expr, int octaves, double k,
                                   const nl_noise_window *win, unsigned long seed, double *v, nl_error *err)
{
  if (kind == NL_GCTBF_CLOUD && !expr) {
    nl_noise_perm3 p;
    nl_noise_perm3_seed(&p, seed);
    nl_noise_basis b = nl_noise_basis_perm3(&p);
    nl_noise_octaves o = nl_noise_octaves_fractal(octaves + 1);
    for (int l = 0; l < o.n; l++) { o.freq[l] *= k; o.amp[l] = -o.amp[l]; }
    nl_noise_fractal_grid(&b, &o, win, v);
    return NL_OK;
  }
  nl_cellular *c;
  nl_status rc = nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, seed, &c, err);
  if (rc) return rc;
  nl_cellular_gctbf_basis gb = {c, {0}};
  rc = nl_cellular_gctbf_parse(kind == NL_GCTBF_FLAME ? "F1" : expr, &gb.g, err);
  if (!rc && kind == NL_GCTBF_CLOUD) nl_cellular_gctbf_cloud_grid(&gb, octaves, k, win, v);
  else if (!rc && kind == NL_GCTBF_FLAME) {
    nl_noise_basis b = nl_cellular_basis_gctbf(&gb);
    nl_noise_octaves o = nl_noise_octaves_fractal(octaves + 1);
    for (int l = 0; l < o.n; l++) o.freq[l] *= k;
    nl_noise_fractal_grid(&b, &o, win, v);
  } else if (!rc) {
    nl_noise_window w = *win;
    w.x0 *= k; w.y0 *= k; w.z *= k; w.size *= k;
    nl_cellular_gctbf_grid(c, &gb.g, &w, v);
  }
  nl_cellular_free(c);
  return rc;
}

void nl_cellular_count_moments(const double *hist, int M, double *mean, double *var)
{
  double n = 0, s1 = 0, s2 = 0;
  for (int m = 0; m <= M; m++) { n += hist[m]; s1 += m * hist[m]; s2 += (double)m * m * hist[m]; }
  *mean = s1 / n;
  *var = s2 / n - *mean * *mean;
}

void nl_cellular_heightfield_shade(const double *height, int w, int h, double spacing,
                                   const double *light, double *out)
{
  for (int r = 0; r < h; r++)
    for (int c = 0; c < w; c++) {
      int cl = c > 0 ? c - 1 : c, cr = c < w - 1 ? c + 1 : c;
      int ru = r > 0 ? r - 1 : r, rd = r < h - 1 ? r + 1 : r;
      /* surface z = -height: gradient of z, normal (-zx, -zy, 1) normalised */
      double zx = -(height[(size_t)r * w + cr] - height[(size_t)r * w + cl]) / ((cr - cl) * spacing);
      double zy = -(height[(size_t)rd * w + c] - height[(size_t)ru * w + c]) / ((rd - ru) * spacing);
      double nx = -zx, ny = -zy, nz = 1.0, len = sqrt(nx * nx + ny * ny + nz * nz);
      double d = (nx * light[0] + ny * light[1] + nz * light[2]) / len;
      out[(size_t)r * w + c] = d > 0.0 ? d : 0.0;
    }
}
