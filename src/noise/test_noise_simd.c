/* test_noise_simd.c - every SIMD level this CPU runs gives the scalar bits.
 * A level the CPU cannot run is reported and the test exits 77 (meson's
 * "skipped", nl_test_skip): passing would claim that level's kernels.
 *
 * Rows (dense and sparse, either direction, negative and large origins, the
 * heap path past the stack columns), batches of points (negative, large,
 * beyond 2^31, 2^52 and 2^62, signed zeros, integers, NaN and infinities)
 * and fractal grids, for 2D tables of power-of-two and other sizes and for
 * the reference and shuffled 3D permutations: compared with memcmp, so
 * signed zeros and NaN payloads count.
 */
#include "noise/nl_noise.h"
#include "nl_test.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NPOINTS 20000   /* points per table and level */
#include "simd/test_simd_rows.h"   /* coord, same, levels, random_row, compared */


static void compare_grad2(size_t m, unsigned long seed)
{
  nl_noise_grad2 *t = nl_noise_grad2_alloc(m);
  nl_noise_grad2_seed(t, seed);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1000 + m);
  double *x = malloc(NPOINTS * sizeof *x), *y = malloc(NPOINTS * sizeof *y);
  double *ref = malloc(NPOINTS * sizeof *ref), *got = malloc(NPOINTS * sizeof *got);
  for (size_t k = 0; k < NPOINTS; k++) { x[k] = coord(r); y[k] = coord(r); }
  nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
  for (size_t k = 0; k < NPOINTS; k++) ref[k] = nl_noise_grad2_eval(t, x[k], y[k]);
  for (int L = 0; L < nlevels; L++) {
    nl_noise_simd_set(levels[L]);
    for (size_t n = 0; n <= 17; n++) {   /* every tail length */
      nl_noise_grad2_points(t, x + 100, y + 100, n, got);
      NL_CHECK(same(got, ref + 100, n));
    }
    nl_noise_grad2_points(t, x, y, NPOINTS, got);
    if (!same(got, ref, NPOINTS)) {
      for (size_t k = 0; k < NPOINTS; k++)
        if (memcmp(&got[k], &ref[k], sizeof *got)) {
          fprintf(stderr, "  grad2 m=%zu %s point (%.17g, %.17g): %.17g, scalar %.17g\n", m,
                  nl_noise_simd_name(levels[L]), x[k], y[k], got[k], ref[k]);
          break;
        }
      NL_CHECK(0);
    }
    compared += NPOINTS;
  }
  double *rref = malloc(MAXROW * sizeof *rref), *rgot = malloc(MAXROW * sizeof *rgot);
  for (int row = 0; row < NROWS; row++) {
    double x0, dx, yy = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
    size_t n;
    random_row(r, &x0, &dx, &n);
    nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
    nl_noise_grad2_row(t, x0, dx, yy, n, rref);
    for (int L = 0; L < nlevels; L++) {
      nl_noise_simd_set(levels[L]);
      nl_noise_grad2_row(t, x0, dx, yy, n, rgot);
      if (!same(rgot, rref, n)) {
        fprintf(stderr, "  grad2 m=%zu %s row x0=%.17g dx=%.17g y=%.17g n=%zu differs\n", m,
                nl_noise_simd_name(levels[L]), x0, dx, yy, n);
        NL_CHECK(0);
      }
      compared += (long)n;
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  free(rref); free(rgot); free(x); free(y); free(ref); free(got);
  gsl_rng_free(r);
  nl_noise_grad2_free(t);
}

NL_TEST(grad2_levels_match_scalar)
{
  find_levels();
  size_t ms[] = {512, 256, 64, 16, 2, 1, 1024, 100, 300, 3, 511};
  for (size_t k = 0; k < sizeof ms / sizeof *ms; k++) compare_grad2(ms[k], 11 + k);
}

static void compare_perm3(const nl_noise_perm3 *p, unsigned long seed)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, seed);
  double *x = malloc(NPOINTS * sizeof *x), *y = malloc(NPOINTS * sizeof *y), *z = malloc(NPOINTS * sizeof *z);
  double *ref = malloc(NPOINTS * sizeof *ref), *got = malloc(NPOINTS * sizeof *got);
  for (size_t k = 0; k < NPOINTS; k++) { x[k] = coord(r); y[k] = coord(r); z[k] = coord(r); }
  nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
  for (size_t k = 0; k < NPOINTS; k++) ref[k] = nl_noise_perm3_eval(p, x[k], y[k], z[k]);
  for (int L = 0; L < nlevels; L++) {
    nl_noise_simd_set(levels[L]);
    for (size_t n = 0; n <= 17; n++) {
      nl_noise_perm3_points(p, x + 100, y + 100, z + 100, n, got);
      NL_CHECK(same(got, ref + 100, n));
    }
    nl_noise_perm3_points(p, x, y, z, NPOINTS, got);
    if (!same(got, ref, NPOINTS)) {
      for (size_t k = 0; k < NPOINTS; k++)
        if (memcmp(&got[k], &ref[k], sizeof *got)) {
          fprintf(stderr, "  perm3 %s point (%.17g, %.17g, %.17g): %.17g, scalar %.17g\n",
                  nl_noise_simd_name(levels[L]), x[k], y[k], z[k], got[k], ref[k]);
          break;
        }
      NL_CHECK(0);
    }
    /* in place: out is the x array */
    double *xx = malloc(NPOINTS * sizeof *xx);
    memcpy(xx, x, NPOINTS * sizeof *xx);
    nl_noise_perm3_points(p, xx, y, z, NPOINTS, xx);
    NL_CHECK(same(xx, ref, NPOINTS));
    free(xx);
    compared += 2 * NPOINTS;
  }
  double *rref = malloc(MAXROW * sizeof *rref), *rgot = malloc(MAXROW * sizeof *rgot);
  for (int row = 0; row < NROWS; row++) {
    double x0, dx, yy = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
    double zz = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
    size_t n;
    random_row(r, &x0, &dx, &n);
    nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
    nl_noise_perm3_row(p, x0, dx, yy, zz, n, rref);
    for (int L = 0; L < nlevels; L++) {
      nl_noise_simd_set(levels[L]);
      nl_noise_perm3_row(p, x0, dx, yy, zz, n, rgot);
      if (!same(rgot, rref, n)) {
        fprintf(stderr, "  perm3 %s row x0=%.17g dx=%.17g y=%.17g z=%.17g n=%zu differs\n",
                nl_noise_simd_name(levels[L]), x0, dx, yy, zz, n);
        NL_CHECK(0);
      }
      compared += (long)n;
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  free(rref); free(rgot); free(x); free(y); free(z); free(ref); free(got);
  gsl_rng_free(r);
}

NL_TEST(perm3_levels_match_scalar)
{
  find_levels();
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  compare_perm3(&p, 5);
  nl_noise_perm3_seed(&p, 9);
  compare_perm3(&p, 6);
}

/* One octave of a sum over points (nl_noise_perm3_points_sum), as its
 * contract states it: the scalar loop here, against every level and the
 * scalar level's own loop, for scales that overflow (1e300), zero and -0,
 * sums starting at -0 and elsewhere, every tail length and a table whose
 * halves differ (the kernels leave those to the scalar code). */
static void sum_reference(const nl_noise_perm3 *p, double f, const double *x, const double *y, const double *z,
                          size_t n, double amp, double *sum, double *top)
{
  *top = 0.0;
  for (size_t k = 0; k < n; k++) {
    double v = nl_noise_perm3_eval(p, f * x[k], f * y[k], f * z[k]);
    if (fabs(v) > *top) *top = fabs(v);
    sum[k] = sum[k] + amp * v;
  }
}

/* A coordinate the batch kernels take whole blocks of: in range, but at
 * the lattice's edges (integers, half-integers, -0, values just below an
 * integer or 0, near multiples of 256, either sign). */
static double tame(gsl_rng *r)
{
  static const double edge[] = {0.0, -0.0, -1e-20, 1e-20, -0x1p-54, -0x1p-53, 0.5, -0.5, 255.0,
                                256.0, -256.0, -255.0, 0x1p31 - 0.5, -0x1p31 + 1, 2147483647.75};
  double u = gsl_rng_uniform(r);
  if (u < 0.05) return edge[gsl_rng_uniform_int(r, sizeof edge / sizeof *edge)];
  if (u < 0.25) return (double)((long)gsl_rng_uniform_int(r, 601) - 300);
  if (u < 0.35) return (double)((long)gsl_rng_uniform_int(r, 601) - 300) + 0.5;
  if (u < 0.45) return nextafter((double)((long)gsl_rng_uniform_int(r, 601) - 300), -INFINITY);
  return 600 * gsl_rng_uniform(r) - 300;
}

/* Batches whose blocks of 64 points the kernels hash at once, and blocks
 * that one awkward point sends to the per-vector path (a cell of -2^31, a
 * coordinate past 2^31, NaN): points, sums of one octave and one bounded
 * term against the point call, at every level. */
NL_TEST(perm3_blocks_match_scalar)
{
  find_levels();
  enum { NB = 64 * 160 + 40 };
  static const double awkward[] = {-0x1p31, -2147483647.5, 0x1p31, NAN, -INFINITY, 1e300};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 33);
  double *c[3], *ref = malloc(NB * sizeof *ref), *got = malloc(NB * sizeof *got);
  for (int a = 0; a < 3; a++) {
    c[a] = malloc(NB * sizeof *c[a]);
    for (size_t k = 0; k < NB; k++) c[a][k] = tame(r);
  }
  for (size_t b = 1; b < NB / 64; b += 3)   /* one awkward coordinate in every third block */
    c[b % 3][64 * b + gsl_rng_uniform_int(r, 64)] = awkward[(b / 3) % 6];
  nl_noise_perm3 p;
  for (int tab = 0; tab < 2; tab++) {
    if (tab) nl_noise_perm3_seed(&p, 12);
    else nl_noise_perm3_reference(&p);
    for (size_t k = 0; k < NB; k++) ref[k] = nl_noise_perm3_eval(&p, c[0][k], c[1][k], c[2][k]);
    for (int L = 0; L < nlevels; L++) {
      nl_noise_simd_set(levels[L]);
      nl_noise_perm3_points(&p, c[0], c[1], c[2], NB, got);
      NL_CHECK(same(got, ref, NB));
      for (int s = 0; s < 2; s++) {   /* f = 1 and f = -1.5, from a sum of -0 */
        double f = s ? -1.5 : 1.0, rs[NB], t0, t1;
        for (size_t k = 0; k < NB; k++) rs[k] = got[k] = -0.0;
        sum_reference(&p, f, c[0], c[1], c[2], NB, 0.75, rs, &t0);
        t1 = nl_noise_perm3_points_sum(&p, f, c[0], c[1], c[2], NB, 0.75, got);
        NL_CHECK(same(got, rs, NB) && memcmp(&t0, &t1, sizeof t0) == 0);
      }
      compared += 3 * NB;
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  for (int a = 0; a < 3; a++) free(c[a]);
  free(ref); free(got);
  gsl_rng_free(r);
}

/* 2D batches of in-range points, with one awkward point in every third
 * vector, for power-of-two tables (whose batches fold the permutation into
 * the gradients) and others, against the point call at every level. */
NL_TEST(grad2_blocks_match_scalar)
{
  find_levels();
  enum { NB = 8 * 1200 + 5 };
  static const double awkward[] = {-0x1p31, -2147483647.5, 0x1p31, NAN, INFINITY, -1e300};
  static const size_t ms[] = {512, 1024, 2048, 256, 1, 2, 300};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 34);
  double *x = malloc(NB * sizeof *x), *y = malloc(NB * sizeof *y);
  double *ref = malloc(NB * sizeof *ref), *got = malloc(NB * sizeof *got);
  for (size_t k = 0; k < NB; k++) {
    x[k] = tame(r);
    y[k] = tame(r);
  }
  for (size_t v = 1; v < NB / 8; v += 3)
    (v % 2 ? x : y)[8 * v + gsl_rng_uniform_int(r, 8)] = awkward[(v / 3) % 6];
  for (size_t a = 0; a < sizeof ms / sizeof *ms; a++) {
    nl_noise_grad2 *t = nl_noise_grad2_alloc(ms[a]);
    nl_noise_grad2_seed(t, 40 + a);
    for (size_t k = 0; k < NB; k++) ref[k] = nl_noise_grad2_eval(t, x[k], y[k]);
    for (int L = 0; L < nlevels; L++) {
      nl_noise_simd_set(levels[L]);
      nl_noise_grad2_points(t, x, y, NB, got);
      NL_CHECK(same(got, ref, NB));
      nl_noise_grad2_points(t, x + 3, y + 3, ms[a] + 1, got);   /* just past the table's size */
      NL_CHECK(same(got, ref + 3, ms[a] + 1));
      compared += NB + (long)ms[a] + 1;
    }
    nl_noise_grad2_free(t);
  }
  nl_noise_simd_set(nl_noise_simd_best());
  free(x);
  free(y);
  free(ref);
  free(got);
  gsl_rng_free(r);
}

static void compare_perm3_sum(const nl_noise_perm3 *p, unsigned long seed)
{
  static const double fs[] = {1.0, 2.0, 2048.0, -3.5, 0.0, -0.0, 1e300, 0x1p20, 0.37};
  static const double amps[] = {0.5, -1.0, 1e-3, 0.0};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, seed);
  double *x = malloc(NPOINTS * sizeof *x), *y = malloc(NPOINTS * sizeof *y), *z = malloc(NPOINTS * sizeof *z);
  double *s0 = malloc(NPOINTS * sizeof *s0), *ref = malloc(NPOINTS * sizeof *ref), *got = malloc(NPOINTS * sizeof *got);
  for (size_t k = 0; k < NPOINTS; k++) {
    int smoke = gsl_rng_uniform(r) < 0.5;   /* A2's unit cube, or the awkward mixture */
    x[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    y[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    z[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    s0[k] = gsl_rng_uniform(r) < 0.2 ? -0.0 : 4 * gsl_rng_uniform(r) - 2;
  }
  for (size_t a = 0; a < sizeof fs / sizeof *fs; a++) {
    double f = fs[a], amp = amps[a % 4], rtop, top;
    size_t n = a % 3 ? NPOINTS : NPOINTS - 1 - a;
    memcpy(ref, s0, NPOINTS * sizeof *ref);
    sum_reference(p, f, x, y, z, n, amp, ref, &rtop);
    for (int L = -1; L < nlevels; L++) {
      nl_noise_simd_set(L < 0 ? NL_NOISE_SIMD_SCALAR : levels[L]);
      for (size_t m = 0; m <= 33; m++) {   /* every tail length */
        double t0;
        memcpy(got, s0, NPOINTS * sizeof *got);
        sum_reference(p, f, x + 7, y + 7, z + 7, m, amp, got + 7, &t0);
        memcpy(got + NPOINTS / 2, s0 + 7, m * sizeof *got);
        top = nl_noise_perm3_points_sum(p, f, x + 7, y + 7, z + 7, m, amp, got + NPOINTS / 2);
        NL_CHECK(same(got + 7, got + NPOINTS / 2, m) && memcmp(&top, &t0, sizeof top) == 0);
      }
      memcpy(got, s0, NPOINTS * sizeof *got);
      top = nl_noise_perm3_points_sum(p, f, x, y, z, n, amp, got);
      if (!same(got, ref, NPOINTS) || memcmp(&top, &rtop, sizeof top) != 0) {
        fprintf(stderr, "  perm3 sum %s f=%g amp=%g differs (top %.17g, scalar %.17g)\n",
                L < 0 ? "scalar" : nl_noise_simd_name(levels[L]), f, amp, top, rtop);
        NL_CHECK(0);
      }
      compared += (long)n;
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  free(x); free(y); free(z); free(s0); free(ref); free(got);
  gsl_rng_free(r);
}

NL_TEST(perm3_sums_match_scalar)
{
  find_levels();
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  compare_perm3_sum(&p, 15);
  nl_noise_perm3_seed(&p, 9);
  compare_perm3_sum(&p, 16);
  p.p[300] ^= 1;   /* halves differ */
  compare_perm3_sum(&p, 17);
}

/* One bounded term (nl_noise_perm3_points_bounded) against its contract
 * written out here: sums, the eq. 5.4 decisions, the packed arrays in
 * order, the ids decided at 1 and the largest |noise|, at every level and
 * every length up to 40 and a long one; bases spread so that points are
 * decided either way and left open. */
enum { BOUNDED_N = 3000 };
typedef struct { double x[BOUNDED_N + 16], y[BOUNDED_N + 16], z[BOUNDED_N + 16], b[BOUNDED_N + 16],
                 s[BOUNDED_N + 16]; int id[BOUNDED_N + 16], hi[BOUNDED_N]; } bounded_arrays;

static size_t bounded_reference(const nl_noise_perm3 *p, double f, double amp, double r, bounded_arrays *a,
                                size_t *n, double *top)
{
  size_t left = 0, nhi = 0;
  for (size_t k = 0; k < *n; k++) {
    double v = nl_noise_perm3_eval(p, f * a->x[k], f * a->y[k], f * a->z[k]);
    if (fabs(v) > *top) *top = fabs(v);
    double sum = a->s[k] + amp * v, t = a->b[k] + sum;
    int lo = t + r <= 0.0, hi = t - r >= 1.0;
    if (hi) a->hi[nhi++] = a->id[k];
    if (lo || hi) continue;
    a->x[left] = a->x[k]; a->y[left] = a->y[k]; a->z[left] = a->z[k];
    a->b[left] = a->b[k]; a->s[left] = sum; a->id[left] = a->id[k];
    left++;
  }
  *n = left;
  return nhi;
}

static int bounded_same(const bounded_arrays *a, const bounded_arrays *b, size_t n, size_t nhi)
{
  return same(a->x, b->x, n) && same(a->y, b->y, n) && same(a->z, b->z, n) && same(a->b, b->b, n) &&
         same(a->s, b->s, n) && memcmp(a->id, b->id, n * sizeof *a->id) == 0 &&
         memcmp(a->hi, b->hi, nhi * sizeof *a->hi) == 0;
}

NL_TEST(perm3_bounded_match_scalar)
{
  find_levels();
  static bounded_arrays init, ref, got;
  static const double fs[] = {2.0, 64.0, 2048.0, -1.5, 1e300};
  static const double rs[] = {1.2, 0.3, 0.0, 0.05, 2.5};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 21);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 4);
  for (size_t k = 0; k < BOUNDED_N; k++) {
    int smoke = gsl_rng_uniform(r) < 0.7;
    init.x[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    init.y[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    init.z[k] = smoke ? gsl_rng_uniform(r) - 0.5 : coord(r);
    init.b[k] = 4 * gsl_rng_uniform(r) - 2;
    init.s[k] = gsl_rng_uniform(r) < 0.1 ? 0.0 : gsl_rng_uniform(r) - 0.5;
    init.id[k] = (int)k * 3 + 1;
  }
  long cases = 0, decided[3] = {0};
  for (size_t c = 0; c < sizeof fs / sizeof *fs; c++)
    for (size_t n0 = 0; n0 <= 41; n0++) {
      size_t n = n0 == 41 ? BOUNDED_N - c : n0, nref = n;
      double tref = 0.25 * (double)(c == 1), amp = c == 3 ? -0.5 : 0.5;
      ref = init;
      size_t hr = bounded_reference(&p, fs[c], amp, rs[c], &ref, &nref, &tref);
      decided[0] += (long)nref; decided[1] += (long)hr; decided[2] += (long)(n - nref - hr);
      for (int L = -1; L < nlevels; L++) {
        nl_noise_simd_set(L < 0 ? NL_NOISE_SIMD_SCALAR : levels[L]);
        got = init;
        nl_noise_pack pk = {got.x, got.y, got.z, got.b, got.s, got.id, n};
        double top = 0.25 * (double)(c == 1);
        size_t hg = nl_noise_perm3_points_bounded(&p, fs[c], amp, rs[c], &pk, got.hi, &top);
        int ok = pk.n == nref && hg == hr && memcmp(&top, &tref, sizeof top) == 0 &&
                 bounded_same(&ref, &got, nref, hr);
        if (!ok) fprintf(stderr, "  bounded %s f=%g n=%zu differs\n", L < 0 ? "scalar" : nl_noise_simd_name(levels[L]),
                         fs[c], n);
        NL_CHECK(ok);
        cases++;
      }
    }
  /* the points went every way: left open, decided at 1, decided at 0 */
  NL_CHECK(decided[0] > 1000 && decided[1] > 1000 && decided[2] > 1000);
  NL_CHECK(cases >= 42 * 5);
  nl_noise_simd_set(nl_noise_simd_best());
  gsl_rng_free(r);
}

/* Rows at the edges of the kernels' shortcuts: x = -0 (whose cell must read
 * +0), x in [-2^-54, 0) (whose fraction rounds to 1 and is mapped to 0),
 * steps at the windows' limits (7 |dx| = 4 and 13) and either side of
 * them, sparse steps (0.7 to 2.5 cells a sample) either way, rows
 * ending at the lattice bound 2^52, and every length up to 3 vectors. */
NL_TEST(edge_rows_match_scalar)
{
  find_levels();
  nl_noise_grad2 *t = nl_noise_grad2_alloc(64);
  nl_noise_grad2_seed(t, 5);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 5);
  const double x0s[] = {-0.0, 0.0, -0x1p-54, -0x1p-55, -1e-20, -0x1p-53, -0x1p-50, -1.0 / 3, 0x1p52 - 40,
                        -0x1p52 + 1, 1e-300, -5e-324};
  const double dxs[] = {1.0 / 64, -1.0 / 64, 4.0 / 7, -4.0 / 7, 0.5714286, 0x1p-60, -0x1p-60, 0.0,
                        -0.0, 1.0, 0.75, 0.7, -0.7, 13.0 / 7, -13.0 / 7, 1.8571429, -1.8571429,
                        1.3, 2.0, -2.5};
  const double ys[] = {-0.0, 0.0, 3.0, -1e-20, 0.25};
  double ref[3 * 8 + 1], got[3 * 8 + 1], acc[3 * 8 + 1];
  int bad = 0;
  for (size_t a = 0; a < sizeof x0s / sizeof *x0s; a++)
    for (size_t d = 0; d < sizeof dxs / sizeof *dxs; d++)
      for (size_t yi = 0; yi < sizeof ys / sizeof *ys; yi++)
        for (size_t n = 1; n <= 3 * 8 + 1; n++)
          for (int which = 0; which < 2; which++) {
            nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
            if (which) nl_noise_perm3_row(&p, x0s[a], dxs[d], ys[yi], -ys[yi], n, ref);
            else nl_noise_grad2_row(t, x0s[a], dxs[d], ys[yi], n, ref);
            for (int L = 0; L < nlevels; L++) {
              nl_noise_simd_set(levels[L]);
              if (which) nl_noise_perm3_row(&p, x0s[a], dxs[d], ys[yi], -ys[yi], n, got);
              else nl_noise_grad2_row(t, x0s[a], dxs[d], ys[yi], n, got);
              if (!same(got, ref, n) && bad++ < 5)
                fprintf(stderr, "  %s row %s x0=%a dx=%a y=%a n=%zu differs\n", which ? "perm3" : "grad2",
                        nl_noise_simd_name(levels[L]), x0s[a], dxs[d], ys[yi], n);
              compared += (long)n;
            }
          }
  NL_CHECK(bad == 0);
  /* the same rows as octave sums (first octave 0 + a v, turbulence) */
  nl_noise_basis b[] = {nl_noise_basis_grad2(t), nl_noise_basis_perm3(&p)};
  nl_noise_octaves o = nl_noise_octaves_fbm(3, -0.5, 2.0);
  for (int tb = 0; tb < 2; tb++, o.turbulence = 1)
    for (size_t a = 0; a < sizeof x0s / sizeof *x0s; a++)
      for (size_t d = 0; d < sizeof dxs / sizeof *dxs; d++)
        for (int bi = 0; bi < 2; bi++) {
          size_t n = 3 * 8 + 1 - a;
          nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
          nl_noise_fractal_row(&b[bi], &o, x0s[a], dxs[d], -0.0, 0.0, n, ref, acc);
          for (int L = 0; L < nlevels; L++) {
            nl_noise_simd_set(levels[L]);
            nl_noise_fractal_row(&b[bi], &o, x0s[a], dxs[d], -0.0, 0.0, n, got, acc);
            NL_CHECK(same(got, ref, n));
            compared += (long)n;
          }
        }
  nl_noise_simd_set(nl_noise_simd_best());
  nl_noise_grad2_free(t);
}

/* The checked batches: the unchecked batches' bits where every point
 * passes, and at a refused point (NaN, infinity, f |c| at 2^52 and just
 * below it, in each coordinate, at block edges and in the tail) its index,
 * the values before it and nothing past its block. */
static int refused_ref(const double *x, const double *y, const double *z, size_t k, double f)
{
  return !(f * fabs(x[k]) < 0x1p52) || !(f * fabs(y[k]) < 0x1p52) ||
         (z && !(f * fabs(z[k]) < 0x1p52));
}

NL_TEST(checked_points)
{
  find_levels();
  enum { N = 2 * NL_NOISE_CHECK_BLOCK + 37 };
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 5);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(64);
  nl_noise_grad2_seed(t, 5);
  nl_noise_octaves fbm = nl_noise_octaves_fbm(5, 0.5, 2.0);   /* finest frequency 16 */
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 77);
  static double x[N], y[N], z[N], ref[N], got[N];
  for (size_t k = 0; k < N; k++) {
    x[k] = 600 * gsl_rng_uniform(r) - 300;
    y[k] = 600 * gsl_rng_uniform(r) - 300;
    z[k] = -1e6 * gsl_rng_uniform(r);
  }
  const size_t at[] = {0, 7, NL_NOISE_CHECK_BLOCK - 1, NL_NOISE_CHECK_BLOCK, N - 1};
  const double bad[] = {NAN, INFINITY, -INFINITY, 0x1p52, -0x1p52};
  int levels_all[5] = {NL_NOISE_SIMD_SCALAR};
  for (int L = 0; L < nlevels; L++) levels_all[L + 1] = levels[L];
  for (int L = 0; L <= nlevels; L++) {
    nl_noise_simd_set(levels_all[L]);
    for (int kind = 0; kind < 3; kind++) {   /* improved, fbm over improved, grad2 */
      const nl_noise_octaves *o = kind == 1 ? &fbm : NULL;
      double f = kind == 1 ? 16.0 : 1.0;
      for (size_t k = 0; k < N; k++) ref[k] = 0.0;
      if (kind == 0) nl_noise_perm3_points(&p, x, y, z, N, ref);
      if (kind == 1)
        for (int l = 0; l < fbm.n; l++)
          nl_noise_perm3_points_sum(&p, fbm.freq[l], x, y, z, N, fbm.amp[l], ref);
      if (kind == 2) nl_noise_grad2_points(t, x, y, N, ref);
      size_t k = kind == 2 ? nl_noise_grad2_points_checked(t, x, y, N, got)
                           : nl_noise_perm3_points_checked(&p, o, x, y, z, N, got);
      NL_CHECK(k == N && same(got, ref, N));
      double *cs[] = {x, y, z};
      for (size_t a = 0; a < sizeof at / sizeof *at; a++)
        for (size_t b = 0; b < sizeof bad / sizeof *bad + 1; b++)
          for (int c = 0; c < (kind == 2 ? 2 : 3); c++) {
            double keep = cs[c][at[a]];
            /* the last case: just below the limit, accepted */
            cs[c][at[a]] = b < sizeof bad / sizeof *bad ? bad[b] / f : nextafter(0x1p52, 0) / f;
            int refuse = b < sizeof bad / sizeof *bad;
            for (size_t q = 0; q < N; q++) got[q] = -7.0;
            k = kind == 2 ? nl_noise_grad2_points_checked(t, x, y, N, got)
                          : nl_noise_perm3_points_checked(&p, o, x, y, z, N, got);
            size_t end = (at[a] / NL_NOISE_CHECK_BLOCK + 1) * NL_NOISE_CHECK_BLOCK;
            NL_CHECK(k == (refuse ? at[a] : N));
            NL_CHECK(nl_noise_points_refused(x, y, kind == 2 ? NULL : z, N, f) == k);
            if (refuse) {
              NL_CHECK(same(got, ref, at[a]));
              for (size_t q = end; q < N; q++) NL_CHECK(got[q] == -7.0);
            }
            cs[c][at[a]] = keep;
          }
    }
    /* a frequency that is not a power of two: the quick test's bound
     * against the exact product, around 2^52 / 3 */
    double f = 3.0, c0 = 0x1p52 / 3;
    for (int d = -4; d <= 4; d++) {
      double c = c0;
      for (int s = 0; s < (d < 0 ? -d : d); s++) c = nextafter(c, d < 0 ? 0 : INFINITY);
      double cx[16], cy[16] = {0};
      for (int q = 0; q < 16; q++) cx[q] = q == 11 ? c : 1.0;
      size_t want = refused_ref(cx, cy, NULL, 11, f) ? 11 : 16;
      NL_CHECK(nl_noise_points_refused(cx, cy, NULL, 16, f) == want);
    }
  }
  nl_noise_simd_set(nl_noise_simd_best());
  gsl_rng_free(r);
  nl_noise_grad2_free(t);
}

/* nl_noise_fractal_points is nl_noise_fractal_row point by point: at a
 * row's samples (dyadic, power-of-two frequencies: exact products) it
 * gives the row's bits, for each basis and turbulence. */
NL_TEST(fractal_points_are_rows)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 9);
  nl_noise_grad2 *t = nl_noise_grad2_alloc(128);
  nl_noise_grad2_seed(t, 9);
  nl_noise_basis bases[] = {nl_noise_basis_perm3(&p), nl_noise_basis_grad2(t)};
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.6, 2.0);
  enum { N = 300 };
  double x[N], y[N], z[N], row[N], got[N], scratch[N];
  for (int tb = 0; tb < 2; tb++, o.turbulence = 1)
    for (int b = 0; b < 2; b++) {
      double x0 = -37.25, dx = 0.015625, yy = -3.5, zz = 11.75;
      for (int k = 0; k < N; k++) { x[k] = x0 + k * dx; y[k] = yy; z[k] = zz; }
      nl_noise_fractal_row(&bases[b], &o, x0, dx, yy, b ? 0.0 : zz, N, row, scratch);
      nl_noise_fractal_points(&bases[b], &o, x, y, b ? NULL : z, N, got);
      NL_CHECK(same(got, row, N));
    }
  nl_noise_grad2_free(t);
}

/* The sums the experiments use (S1-S4): fBm grids over both bases. */
NL_TEST(fractal_grids_match_scalar)
{
  find_levels();
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512), *t3 = nl_noise_grad2_alloc(300);
  nl_noise_grad2_seed(t, 3);
  nl_noise_grad2_seed(t3, 3);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 3);
  nl_noise_basis bases[] = {nl_noise_basis_grad2(t), nl_noise_basis_grad2(t3), nl_noise_basis_perm3(&p)};
  nl_noise_octaves octs[] = {nl_noise_octaves_fbm(4, 0.5, 2.0), nl_noise_octaves_cheng(6, 2.0, 1.0), nl_noise_octaves_fbm(9, 0.7, 2.1)};
  octs[2].turbulence = 1;
  nl_noise_window wins[] = {{0, 0, 0.5, 16, 96, 40}, {-37.25, 11.5, -3.75, 3, 130, 7}, {1e6, -1e6, 2.5, 1e3, 33, 9}};
  size_t npix = 130 * 40;
  double *ref = malloc(npix * sizeof *ref), *got = malloc(npix * sizeof *got);
  for (int b = 0; b < 3; b++)
    for (int o = 0; o < 3; o++)
      for (int w = 0; w < 3; w++) {
        size_t np = (size_t)wins[w].w * (size_t)wins[w].h;
        nl_noise_simd_set(NL_NOISE_SIMD_SCALAR);
        nl_noise_fractal_grid(&bases[b], &octs[o], &wins[w], ref);
        for (int L = 0; L < nlevels; L++) {
          nl_noise_simd_set(levels[L]);
          nl_noise_fractal_grid(&bases[b], &octs[o], &wins[w], got);
          if (!same(got, ref, np)) {
            fprintf(stderr, "  grid basis %d octaves %d window %d level %s differs\n", b, o, w,
                    nl_noise_simd_name(levels[L]));
            NL_CHECK(0);
          }
          compared += (long)np;
        }
      }
  nl_noise_simd_set(nl_noise_simd_best());
  printf("  %ld values compared bit for bit with the scalar path\n", compared);
  free(ref); free(got);
  nl_noise_grad2_free(t); nl_noise_grad2_free(t3);
}

int main(void) { return nl_test_run(); }
