/* test_cellular_reference.c - cellular F1..F4 and the GCTBF against a brute
 * force written apart from the library (tests/reference/worley_cellular.c:
 * its own hash, splitmix64, Poisson table and count rules, every feature
 * point of the cubes within reach listed and sorted).
 *
 * Tables: four (lambda 4 with each count rule, and a sparse lambda 0.4,
 * where fewer than n points in the 27 cubes and F_n > 1 are common), the
 * permutation the library drew from each seed. Compared:
 *  - feature points of 20,000 random cubes a table (indices up to 10^6 of
 *    either sign, and next to multiples of 2^16, where PERM wraps): the
 *    count and every coordinate, bit for bit;
 *  - nl_cellular_eval at 2^14 points a table, n = 1..4, against the
 *    27-cube brute force (the library's contract), bit for bit, and against
 *    Worley's F_i (125 cubes) where that is <= 1, bit for bit: there no
 *    point outside the 27 cubes can enter. Where Worley's F_i > 1 the
 *    27-cube value may be larger (never smaller); the share is printed;
 *  - nl_cellular_row at every SIMD level this CPU runs, 60 rows a table;
 *  - nl_cellular_gctbf_row for four expressions, against sum c_i F_i +
 *    sum c_ij F_i F_j from the brute force.
 * Points: uniform in [-100, 100], or one time in two a cube face (an
 * integer), a half-integer, an ulp off an integer, a tiny value of either
 * sign, or next to a multiple of 2^16.
 *
 * Tolerance 0 for F: both sides form (dx dx + dy dy) + dz dz from the same
 * doubles ((double)i + u, u = k 2^-53) and take a correctly rounded sqrt;
 * the n smallest of a set do not depend on the order it is scanned in.
 * GCTBF: 1e-13 relative to sum |c| FMAX^2, the same products summed in
 * another order (linear terms first here), a dozen roundings.
 */
#include "cellular/nl_cellular.h"
#include "simd/nl_simd.h"
#include "nl_test.h"
#include "reference/worley_cellular.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NPOINTS (1 << 14)
#define NCUBES 20000
#define NROWS 60
#define ROW 200

static const struct { double lambda; nl_cellular_count_rule rule; int ref_rule; } tables[] = {
  {4.0, NL_COUNT_INVERSE_CDF, WORLEY_INVERSE_CDF},
  {4.0, NL_COUNT_CLOSEST, WORLEY_CLOSEST_FIRST},
  {4.0, NL_COUNT_CLOSEST_LAST, WORLEY_CLOSEST_LAST},
  {0.4, NL_COUNT_INVERSE_CDF, WORLEY_INVERSE_CDF}};
#define NTABLES (sizeof tables / sizeof *tables)

static nl_cellular *make(size_t t, worley_ref *w)
{
  nl_cellular *c = NULL;
  NL_CHECK(nl_cellular_alloc(tables[t].lambda, 50, tables[t].rule, 31 + t, &c, NULL) == NL_OK);
  worley_ref_init(w, c->perm, tables[t].lambda, 50, tables[t].ref_rule);
  return c;
}

static double coord(gsl_rng *r)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5) return 200 * gsl_rng_uniform(r) - 100;
  double m = (double)((long)gsl_rng_uniform_int(r, 201) - 100);
  double s = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  if (u < 0.65) return m;
  if (u < 0.75) return m + 0.5;
  if (u < 0.85) return nextafter(m, s * INFINITY);
  if (u < 0.92) return s * ldexp(1.0, -1 - (int)gsl_rng_uniform_int(r, 1074));
  return 65536.0 * (double)((long)gsl_rng_uniform_int(r, 5) - 2) + s * gsl_rng_uniform(r);
}

/* The library's contract on the brute force's squared distances. */
static void to_f(const double d2[4], double F[4])
{
  for (int q = 0; q < 4; q++)
    F[q] = d2[q] < NL_CELLULAR_FMAX * NL_CELLULAR_FMAX ? sqrt(d2[q]) : NL_CELLULAR_FMAX;
}

NL_TEST(feature_points_match)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1996);
  long bad = 0, points = 0;
  for (size_t t = 0; t < NTABLES; t++) {
    worley_ref w;
    nl_cellular *c = make(t, &w);
    for (int q = 0; q < NCUBES; q++) {
      long ijk[3];
      for (int a = 0; a < 3; a++)
        ijk[a] = q % 2 ? (long)gsl_rng_uniform_int(r, 2000001) - 1000000
                       : 65536 * ((long)gsl_rng_uniform_int(r, 5) - 2)
                         + (long)gsl_rng_uniform_int(r, 5) - 2;
      double a[3 * NL_CELLULAR_MAX_M], b[3 * NL_CELLULAR_MAX_M];
      int ma = nl_cellular_cube(c, ijk[0], ijk[1], ijk[2], a);
      int mb = worley_ref_cube(&w, ijk[0], ijk[1], ijk[2], b);
      bad += ma != mb || memcmp(a, b, 3 * (size_t)ma * sizeof *a) != 0;
      points += mb;
    }
    nl_cellular_free(c);
  }
  printf("  %zu x %d cubes, %ld feature points, %ld cubes differ\n", NTABLES, NCUBES, points, bad);
  NL_CHECK(bad == 0);
  gsl_rng_free(r);
}

NL_TEST(points_match_brute_force)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2000);
  for (size_t t = 0; t < NTABLES; t++) {
    worley_ref w;
    nl_cellular *c = make(t, &w);
    long bad27 = 0, badw = 0, beyond = 0, larger = 0, below = 0;
    for (int k = 0; k < NPOINTS; k++) {
      double p[3] = {coord(r), coord(r), coord(r)}, got[4], d2[4], want[4], worley[4];
      int n = 1 + k % 4;
      nl_cellular_eval(c, p, n, got);
      worley_ref_d2(&w, p, 1, d2);
      to_f(d2, want);
      bad27 += memcmp(got, want, (size_t)n * sizeof *got) != 0;
      if (k % 4)
        continue;   /* Worley's F_i (125 cubes) at a quarter of the points */
      worley_ref_d2(&w, p, 2, d2);
      for (int q = 0; q < n; q++) {
        worley[q] = sqrt(d2[q]);
        if (worley[q] <= 1.0) {
          badw += got[q] != worley[q];
          continue;
        }
        beyond++;
        larger += got[q] > worley[q];
        below += got[q] < worley[q];
      }
    }
    printf("  lambda %.1f %-12s %d points: %ld differ from the 27-cube brute force;"
           " F_i > 1 at %ld, 27-cube value larger at %ld\n", tables[t].lambda,
           nl_cellular_count_rule_name(tables[t].rule), NPOINTS, bad27, beyond, larger);
    NL_CHECK(bad27 == 0 && badw == 0 && below == 0);
    nl_cellular_free(c);
  }
  gsl_rng_free(r);
}

NL_TEST(rows_and_gctbf_match_brute_force)
{
  static const char *exprs[] = {"F1", "F2 - F1", "F2 - F1 - F1F1", "0.5*F1 + 2 F3*F4 - F2F2"};
  static const double steps[] = {1.0 / 64, 0.0137, -0.29, 0.5, 1.0, 1.7, -1.0 / 3, 1e-9};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2005);
  double *want = malloc(4 * ROW * sizeof *want), *got = malloc(4 * ROW * sizeof *got);
  long bad = 0, values = 0;
  double gworst = 0;
  for (size_t t = 0; t < NTABLES; t++) {
    worley_ref w;
    nl_cellular *c = make(t, &w);
    for (int row = 0; row < NROWS; row++) {
      double x0 = coord(r), y = coord(r), z = coord(r), dx = steps[row % 8];
      int n = 1 + row % 4;
      for (int k = 0; k < ROW; k++) {
        double p[3] = {x0 + (double)k * dx, y, z}, d2[4];
        worley_ref_d2(&w, p, 1, d2);
        to_f(d2, want + 4 * k);
      }
      for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
        if (!nl_simd_supported(l))
          continue;
        nl_simd_set(l);
        nl_cellular_row(c, x0, dx, y, z, ROW, n, got);
        for (int k = 0; k < ROW; k++)
          bad += memcmp(got + n * k, want + 4 * k, (size_t)n * sizeof *got) != 0;
        values += ROW;
      }
      nl_simd_set(nl_simd_best());
      nl_cellular_gctbf g;
      NL_CHECK(nl_cellular_gctbf_parse(exprs[row % 4], &g, NULL) == NL_OK);
      nl_cellular_gctbf_row(c, &g, x0, dx, y, z, ROW, got);
      double scale = 0;
      for (int i = 0; i < 4; i++) {
        scale += fabs(g.c[i]) * NL_CELLULAR_FMAX;
        for (int j = 0; j < 4; j++)
          scale += fabs(g.cc[i][j]) * NL_CELLULAR_FMAX * NL_CELLULAR_FMAX;
      }
      for (int k = 0; k < ROW; k++) {
        const double *F = want + 4 * k;
        double v = 0;
        for (int i = 0; i < 4; i++)
          v += g.c[i] * F[i];
        for (int i = 0; i < 4; i++)
          for (int j = 0; j < 4; j++)
            v += g.cc[i][j] * F[i] * F[j];
        gworst = fmax(gworst, fabs(got[k] - v) / scale);
      }
    }
    nl_cellular_free(c);
  }
  printf("  %ld row values over the levels, %ld differ; GCTBF max relative error %.3g\n",
         values, bad, gworst);
  NL_CHECK(bad == 0);
  NL_CHECK(gworst <= 1e-13);
  free(want);
  free(got);
  gsl_rng_free(r);
}

/* Q1's count statistics: nl_cellular_count_histogram over blocks of cubes
 * (origins of either sign, across PERM's 2^16 wrap) against the counts of
 * the oracle's cubes, exactly; nl_cellular_count_moments against the mean
 * and population variance of those counts in long double (1e-14
 * relative: the library forms E[m^2] - mean^2, which cancels digits where
 * the variance is small against the mean square); measured 1.6e-15. */
NL_TEST(count_histogram_and_moments_match)
{
  static const long origins[] = {0, -20, 65530, -65545, 1000};
  double worst = 0;
  long bad = 0;
  for (size_t t = 0; t < NTABLES; t++) {
    worley_ref w;
    nl_cellular *c = make(t, &w);
    for (size_t q = 0; q < sizeof origins / sizeof *origins; q++) {
      int side = 12 + (int)q;
      double hist[51], want[51] = {0}, pts[3 * NL_CELLULAR_MAX_M];
      nl_cellular_count_histogram(c, origins[q], side, hist);
      long double s1 = 0, s2 = 0, cubes = 0;
      for (long i = origins[q]; i < origins[q] + side; i++)
        for (long j = origins[q]; j < origins[q] + side; j++)
          for (long k = origins[q]; k < origins[q] + side; k++) {
            int m = worley_ref_cube(&w, i, j, k, pts);
            want[m]++;
            s1 += m;
            s2 += (long double)m * m;
            cubes++;
          }
      for (int m = 0; m <= 50; m++)
        bad += hist[m] != want[m];
      double mean, var;
      nl_cellular_count_moments(hist, 50, &mean, &var);
      long double wm = s1 / cubes, wv = s2 / cubes - wm * wm;
      worst = fmax(worst, fabs((double)((mean - wm) / wm)));
      worst = fmax(worst, fabs((double)((var - wv) / wv)));
    }
    nl_cellular_free(c);
  }
  printf("  histograms: %ld bins differ; moments max relative error %.3g\n", bad, worst);
  NL_CHECK(bad == 0);
  NL_CHECK(worst <= 1e-14);
}

int main(void) { return nl_test_run(); }
