/* test_simd_rows.h - what the SIMD tests of noise and wavelet share: a
 * coordinate mixture with the awkward doubles (signed zeros, lattice
 * points, 2^31, 2^52, 2^62, NaN, infinities), random rows (dense, sparse,
 * either direction, past the stack columns), the levels this CPU runs
 * beside scalar, a bitwise comparison and the count of values compared.
 * Include from one test file per program. */
#ifndef TEST_SIMD_ROWS_H
#define TEST_SIMD_ROWS_H

#include "simd/nl_simd.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define NROWS 300       /* rows per table and level */
#define MAXROW 2600

static long compared;

/* A coordinate from a mixture: mostly ordinary, some awkward. */
static double coord(gsl_rng *r)
{
  static const double special[] = {0.0, -0.0, 1.0, -1.0, 255.0, 256.0, -256.0, 0.5, -0.5,
    -1e-20, 1e-20, 0x1p31 - 0.5, -0x1p31, 0x1p31, -0x1p31 - 1, 0x1p52 - 0.5, 0x1p52, -0x1p52,
    0x1p62, -0x1p62, 0x1p63, 1e300, -1e300, 5e-324, INFINITY, -INFINITY, NAN, 0x1p31 - 1,
    2147483647.75, -2147483648.25};
  double u = gsl_rng_uniform(r);
  if (u < 0.05) return special[gsl_rng_uniform_int(r, sizeof special / sizeof *special)];
  if (u < 0.10) return (double)((long)gsl_rng_uniform_int(r, 2001) - 1000);          /* lattice */
  if (u < 0.15)   /* any scale */
    return ldexp(gsl_rng_uniform(r) - 0.5, (int)gsl_rng_uniform_int(r, 70));
  if (u < 0.20) return -1e9 * gsl_rng_uniform(r);
  return 600 * gsl_rng_uniform(r) - 300;
}

static int same(const double *a, const double *b, size_t n)
{
  return memcmp(a, b, n * sizeof *a) == 0;
}

static int levels[4], nlevels;
static void find_levels(void)
{
  if (nlevels) return;
  for (int l = NL_SIMD_SSE2; l <= NL_SIMD_AVX512; l++) {
    if (nl_simd_supported(l))
      levels[nlevels++] = l;
    else
      nl_test_skip("the %s level: not compared, this CPU cannot run it", nl_simd_name(l));
  }
  printf("  SIMD levels this CPU runs beside scalar:");
  for (int k = 0; k < nlevels; k++) printf(" %s", nl_simd_name(levels[k]));
  printf(" (best: %s)\n", nl_simd_name(nl_simd_best()));
}

/* A random row: origin, step (dense, sparse, negative, zero, tiny), length. */
static void random_row(gsl_rng *r, double *x0, double *dx, size_t *n)
{
  static const double steps[] = {1.0 / 64, 0.0137, -0.29, 3.7, 1e-4, 0.0, -1.0 / 64, 0.125, 0.75,
                                 1.0, -2.5, 1e-12, 7.0 / 3};
  *x0 = gsl_rng_uniform(r) < 0.8 ? 200 * gsl_rng_uniform(r) - 100 : coord(r);
  if (gsl_rng_uniform(r) < 0.7)
    *dx = steps[gsl_rng_uniform_int(r, sizeof steps / sizeof *steps)];
  else
    *dx = (gsl_rng_uniform(r) - 0.5) * ldexp(1, (int)gsl_rng_uniform_int(r, 8) - 4);
  double u = gsl_rng_uniform(r);
  if (u < 0.1)
    *n = 1 + gsl_rng_uniform_int(r, 9);
  else if (u < 0.2)   /* past the stack columns */
    *n = 1040 + gsl_rng_uniform_int(r, MAXROW - 1040);
  else
    *n = 1 + gsl_rng_uniform_int(r, 1100);
}

#endif
