/* Tests of nl_sort.c (nl_stats_sort, nl_stats_argsort) against the C
 * library's qsort, which is the independent tool here: exact agreement. */
#include "stats/nl_stats.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_d(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

typedef struct { double v; size_t i; } vi;

static int cmp_vi(const void *a, const void *b)
{
  const vi *x = a, *y = b;
  if (x->v != y->v) return (x->v > y->v) - (x->v < y->v);
  return (x->i > y->i) - (x->i < y->i);
}

/* One value of data kind 0 wide, 1 narrow (skipped passes), 2 ties,
 * 3 signed zeros, 4 infinities. */
static double sample(gsl_rng *rng, int kind)
{
  double u = gsl_rng_uniform(rng);
  switch (kind) {
  case 0: return (u - 0.5) * pow(10, (double)gsl_rng_uniform_int(rng, 40) - 20);
  case 1: return 0.5 + u * 1e-3;
  case 2: return (double)gsl_rng_uniform_int(rng, 7) - 3;
  case 3:
    if (gsl_rng_uniform_int(rng, 3) == 0) return -0.0;
    return gsl_rng_uniform_int(rng, 2) ? 0.0 : u - 0.5;
  default: return gsl_rng_uniform_int(rng, 50) == 0 ? (u < 0.5 ? -INFINITY : INFINITY) : u - 0.5;
  }
}

/* Both paths (introsort below 4096 values, radix from there; argsort is
 * always radix) against qsort: the same values in the same
 * order (bit for bit; -0 and +0 are equal, so only their multiset within a
 * run of zeros is compared), on wide, narrow (skipped passes), negative,
 * tied, signed-zero and infinite data; argsort against qsort by (value,
 * index), the by-example gaussianization's old order. */
NL_TEST(radix_sort_matches_qsort)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  size_t sizes[] = {1, 2, 17, 100, 4095, 4096, 4097, 9001, 65536};
  for (int kind = 0; kind < 5; kind++)
    for (size_t si = 0; si < sizeof sizes / sizeof *sizes; si++) {
      size_t n = sizes[si];
      double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
      vi *r = malloc(n * sizeof *r);
      size_t *order = malloc(n * sizeof *order);
      for (size_t i = 0; i < n; i++) {
        a[i] = sample(rng, kind);
        r[i].v = a[i];
        r[i].i = i;
      }
      memcpy(b, a, n * sizeof *a);
      nl_stats_argsort(a, n, order);
      qsort(r, n, sizeof *r, cmp_vi);
      int same = 1;
      for (size_t i = 0; i < n; i++) same &= order[i] == r[i].i;
      NL_CHECK(same);
      nl_stats_sort(a, n);
      qsort(b, n, sizeof *b, cmp_d);
      size_t neg_a = 0, neg_b = 0;
      for (size_t i = 0; i < n; i++) {
        if (a[i] == 0 && b[i] == 0) {
          neg_a += signbit(a[i]) != 0;
          neg_b += signbit(b[i]) != 0;
          continue;
        }
        same &= memcmp(&a[i], &b[i], sizeof a[i]) == 0;
      }
      NL_CHECK(same && neg_a == neg_b);
      free(a); free(b); free(r); free(order);
    }
  gsl_rng_free(rng);
}

int main(void) { return nl_test_run(); }
