/* test_cellular_simd.c - the per-cube rejection and every SIMD level this
 * CPU runs give the bits of the full 27-cube scan. A level the CPU cannot
 * run is reported and the test exits 77 (meson's "skipped", nl_test_skip):
 * passing would claim that level's kernels.
 *
 * The reference below is the full scan without the rejection (every cube,
 * in i, j, k order, insertion into the n smallest). Points (ordinary,
 * lattice, negative, large, beyond 2^52 and 2^62, signed zeros, NaN,
 * infinities) through nl_cellular_eval, and rows
 * (dense and sparse, either direction, zero and tiny steps, lanes across
 * cube columns, odd lengths for the vector tails) through nl_cellular_row at
 * every level, for n = 1..4 and the three count rules: compared with memcmp.
 */
#include "cellular/nl_cellular.h"
#include "cellular/nl_cellular_simd.h"
#include "noise/nl_noise.h"
#include "nl_test.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NPOINTS 4000   /* per table */
#define NROWS 60       /* per table */
#define MAXROW 700

/* The full scan: all 27 cubes around the point, none rejected. */
static void ref_eval(const nl_cellular *c, const double *xyz, int n, double *F)
{
  double pts[3 * NL_CELLULAR_MAX_M], d2[NL_CELLULAR_NMAX];
  for (int q = 0; q < n; q++) d2[q] = INFINITY;
  if (!(fabs(xyz[0]) < 0x1p52 && fabs(xyz[1]) < 0x1p52 && fabs(xyz[2]) < 0x1p52)) {
    nl_cellular_eval(c, xyz, n, F);   /* the full scan there by construction (no rejection) */
    return;
  }
  long i = (long)floor(xyz[0]), j = (long)floor(xyz[1]), k = (long)floor(xyz[2]);
  for (long di = -1; di <= 1; di++)
    for (long dj = -1; dj <= 1; dj++)
      for (long dk = -1; dk <= 1; dk++) {
        int m = nl_cellular_cube(c, i + di, j + dj, k + dk, pts);
        for (int p = 0; p < m; p++) {
          double ax = pts[3 * p] - xyz[0], ay = pts[3 * p + 1] - xyz[1], az = pts[3 * p + 2] - xyz[2];
          double v = ax * ax + ay * ay + az * az;
          if (v >= d2[n - 1]) continue;
          int q = n - 1;
          while (q > 0 && d2[q - 1] > v) { d2[q] = d2[q - 1]; q--; }
          d2[q] = v;
        }
      }
  for (int q = 0; q < n; q++)
    F[q] = d2[q] < NL_CELLULAR_FMAX * NL_CELLULAR_FMAX ? sqrt(d2[q]) : NL_CELLULAR_FMAX;
}

static double coord(gsl_rng *r)
{
  static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 255.0, -256.0, 1e-20, -1e-20,
    0x1p31, -0x1p31 - 1, 0x1p52 - 0.5, 0x1p52, -0x1p52, 0x1p62, -0x1p62, 1e300, 5e-324,
    INFINITY, -INFINITY, NAN};
  double u = gsl_rng_uniform(r);
  if (u < 0.05) return special[gsl_rng_uniform_int(r, sizeof special / sizeof *special)];
  if (u < 0.12) return (double)((long)gsl_rng_uniform_int(r, 2001) - 1000);   /* cube faces */
  if (u < 0.17) return ldexp(gsl_rng_uniform(r) - 0.5, (int)gsl_rng_uniform_int(r, 60));
  return 200 * gsl_rng_uniform(r) - 100;
}

static int levels[4], nlevels;
static long compared;

NL_TEST(visit_order_is_a_permutation)
{
  int seen[27] = {0};
  for (int t = 0; t < 27; t++) seen[nl_cellular_visit[t]]++;
  for (int t = 0; t < 27; t++) NL_CHECK(seen[t] == 1);
  NL_CHECK(nl_cellular_visit[0] == 0);   /* the sample's own cube first */
}

static void compare(nl_cellular_count_rule rule, unsigned long seed)
{
  nl_cellular *c = NULL;
  NL_CHECK(nl_cellular_alloc(rule == NL_COUNT_CLOSEST ? 1.5 : 4.0, 50, rule, seed, &c, NULL) == NL_OK);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 77 + seed);
  long bad = 0;
  for (int k = 0; k < NPOINTS; k++) {   /* points: the rejection alone */
    double p[3] = {coord(r), coord(r), coord(r)}, a[4], b[4];
    int n = 1 + (int)gsl_rng_uniform_int(r, 4);
    ref_eval(c, p, n, a);
    nl_cellular_eval(c, p, n, b);
    if (memcmp(a, b, (size_t)n * sizeof *a)) {
      if (!bad++) fprintf(stderr, "  eval (%.17g, %.17g, %.17g) n=%d differs\n", p[0], p[1], p[2], n);
    }
    compared++;
  }
  static const double steps[] = {1.0 / 64, 0.0137, -0.29, 1.7, 1e-4, 0.0, -1.0 / 64, 0.125, 0.75, 1.0, -2.1,
                                 1e-12};
  double *ref = malloc(4 * MAXROW * sizeof *ref), *got = malloc(4 * MAXROW * sizeof *got);
  for (int row = 0; row < NROWS; row++) {
    double x0 = gsl_rng_uniform(r) < 0.85 ? 200 * gsl_rng_uniform(r) - 100 : coord(r);
    double dx = gsl_rng_uniform(r) < 0.7 ? steps[gsl_rng_uniform_int(r, sizeof steps / sizeof *steps)]
                                         : (gsl_rng_uniform(r) - 0.5) * ldexp(1, (int)gsl_rng_uniform_int(r, 6) - 3);
    double y = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
    double z = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
    if (gsl_rng_uniform(r) < 0.1) y = floor(y);   /* on a face */
    size_t cnt = 1 + gsl_rng_uniform_int(r, gsl_rng_uniform(r) < 0.2 ? 17 : MAXROW);
    int n = 1 + (int)gsl_rng_uniform_int(r, 4);
    for (size_t s = 0; s < cnt; s++) {
      double p[3] = {x0 + (double)s * dx, y, z};
      ref_eval(c, p, n, ref + s * (size_t)n);
    }
    for (int L = 0; L < nlevels; L++) {
      nl_simd_set(levels[L]);
      memset(got, 0xa5, 4 * MAXROW * sizeof *got);
      nl_cellular_row(c, x0, dx, y, z, cnt, n, got);
      if (memcmp(ref, got, cnt * (size_t)n * sizeof *ref)) {
        if (!bad++)
          fprintf(stderr, "  row %s x0=%.17g dx=%.17g y=%.17g z=%.17g count=%zu n=%d differs\n",
                  nl_simd_name(levels[L]), x0, dx, y, z, cnt, n);
      }
      compared += (long)cnt;
    }
  }
  nl_simd_set(nl_simd_best());
  NL_CHECK(bad == 0);
  free(ref); free(got);
  gsl_rng_free(r);
  nl_cellular_free(c);
}

NL_TEST(every_level_gives_the_full_scan_bits)
{
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
    if (nl_simd_supported(l))
      levels[nlevels++] = l;
    else
      nl_test_skip("the %s level: not compared, this CPU cannot run it", nl_simd_name(l));
  }
  printf("  levels:");
  for (int k = 0; k < nlevels; k++) printf(" %s", nl_simd_name(levels[k]));
  printf("\n");
  NL_CHECK(nlevels >= (NL_SIMD_X86 ? 2 : 1));   /* x86-64: scalar and SSE2 at least */
  compare(NL_COUNT_INVERSE_CDF, 1);
  compare(NL_COUNT_INVERSE_CDF, 12);
  compare(NL_COUNT_CLOSEST, 3);        /* lambda 1.5: sparse cubes, F_n beyond 1 */
  compare(NL_COUNT_CLOSEST_LAST, 5);   /* many points per cube (r near 0 gives M) */
  printf("  %ld samples compared\n", compared);
}

int main(void) { return nl_test_run(); }
