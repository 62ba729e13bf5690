/* test_cluster_reference.c - every linkage of nl_cluster_linkage against
 * clustering by its definition (tests/reference/naive_linkage.c: each
 * step scores every pair of clusters from their points, O(n^3) and more,
 * no distance matrix, no Lance-Williams update, no chain).
 *
 * Point sets: 250 a method, n from 2 to 50, dimension 1 to 6, drawn
 * uniform in [-10, 10]^d, as Gaussian blobs, or uniform around 1e6 (the
 * differences cancel most digits of the coordinates). A set whose closest
 * and next closest pairs are within 1e-9 of each other at some step (a
 * near-tie that rounding may order either way) is skipped and counted;
 * continuous random points make these rare.
 *
 * Compared: each row's merged ids and size exactly, its height within a
 * relative tolerance. Single and complete heights are point distances, the
 * same squares summed in 8 lanes there and in order here (for d <= 8 the
 * same order): measured 0; tolerance 1e-13. Average, a weighted mean
 * updated merge by merge there and the mean of the |A||B| distances here,
 * about n roundings of values of one size: measured 1.5e-15; 1e-13. Ward,
 * Lance-Williams on squared heights there, whose last term is subtracted
 * and cancels digits, centroids here (taken relative to the first point,
 * so that the sets around 1e6 keep their digits: from absolute coordinates
 * the oracle itself was off by 1.4e-8): measured 1.4e-13 (6.4e-13 on 300
 * sets of up to 60 points); 1e-11.
 */
#include "stats/nl_cluster.h"
#include "nl_test.h"
#include "reference/naive_linkage.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#define NSETS 250
#define MAXN 50

static size_t make_set(gsl_rng *r, double *x, size_t *d)
{
  size_t n = 2 + gsl_rng_uniform_int(r, MAXN - 1);
  *d = 1 + gsl_rng_uniform_int(r, 6);
  int kind = (int)gsl_rng_uniform_int(r, 3);
  double centre[4][6];
  for (int c = 0; c < 4; c++)
    for (size_t j = 0; j < *d; j++)
      centre[c][j] = gsl_ran_gaussian(r, 8.0);
  for (size_t p = 0; p < n; p++) {
    int c = (int)gsl_rng_uniform_int(r, 4);
    for (size_t j = 0; j < *d; j++) {
      double *v = x + p * *d + j;
      if (kind == 0)
        *v = 20 * gsl_rng_uniform(r) - 10;
      else if (kind == 1)
        *v = centre[c][j] + gsl_ran_gaussian(r, 1.0);
      else
        *v = 1e6 + gsl_rng_uniform(r);
    }
  }
  return n;
}

NL_TEST(every_linkage_matches_the_naive_agglomeration)
{
  static const struct {
    nl_cluster_linkage_method m;
    int ref;
    const char *name;
    double tol;
  } methods[] = {
    {NL_LINKAGE_SINGLE, NAIVE_SINGLE, "single", 1e-13},
    {NL_LINKAGE_COMPLETE, NAIVE_COMPLETE, "complete", 1e-13},
    {NL_LINKAGE_AVERAGE, NAIVE_AVERAGE, "average", 1e-13},
    {NL_LINKAGE_WARD, NAIVE_WARD, "ward", 1e-11}};
  double *x = malloc(MAXN * 6 * sizeof *x), Z[4 * MAXN], R[4 * MAXN];
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1963);
  for (size_t mi = 0; mi < 4; mi++) {
    long sets = 0, skipped = 0, rows = 0, bad = 0;
    double worst = 0;
    for (int s = 0; s < NSETS; s++) {
      size_t d, n = make_set(r, x, &d);
      double gap;
      naive_linkage(x, n, d, methods[mi].ref, R, &gap);
      if (gap < 1e-9) {
        skipped++;
        continue;
      }
      NL_CHECK(nl_cluster_linkage(x, n, d, methods[mi].m, Z, NULL) == NL_OK);
      sets++;
      for (size_t i = 0; i + 1 < n; i++) {
        double rel = fabs(Z[4 * i + 2] - R[4 * i + 2]) / R[4 * i + 2];
        int same = Z[4 * i] == R[4 * i] && Z[4 * i + 1] == R[4 * i + 1]
                && Z[4 * i + 3] == R[4 * i + 3];
        if ((!same || !(rel <= methods[mi].tol)) && !bad++)
          printf("  %s n=%zu d=%zu row %zu: {%g %g %.17g %g}, naive {%g %g %.17g %g}\n",
                 methods[mi].name, n, d, i, Z[4 * i], Z[4 * i + 1], Z[4 * i + 2], Z[4 * i + 3],
                 R[4 * i], R[4 * i + 1], R[4 * i + 2], R[4 * i + 3]);
        worst = fmax(worst, rel);
        rows++;
      }
    }
    printf("  %-8s %ld sets (%ld near-ties skipped), %ld merges, %ld differ,"
           " max relative height error %.3g\n", methods[mi].name, sets, skipped, rows, bad, worst);
    NL_CHECK(bad == 0);
    NL_CHECK(skipped <= NSETS / 20);
  }
  gsl_rng_free(r);
  free(x);
}

int main(void) { return nl_test_run(); }
