/* test_gof_reference.c - KS and Kuiper statistics and the laws of D against
 * their definitions (tests/reference/ks_direct.c), at thousands of inputs.
 * What each comparison's tolerance is, and why, is said where it is checked;
 * the measured worst case of each is printed.
 */
#include "stats/nl_stats.h"
#include "nl_test.h"
#include "reference/ks_direct.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

/* The three named laws, written here: uniform on [a, b), the normal by
 * erfc, the exponential by expm1 (the library's may differ by an ulp). */
static double loc, scale;
static double cdf_uniform(double x) { return fmin(1, fmax(0, (x - loc) / scale)); }
static double cdf_norm(double x) { return 0.5 * erfc(-(x - loc) / scale / sqrt(2.0)); }
static double cdf_expon(double x) { return x <= loc ? 0 : -expm1(-(x - loc) / scale); }

/* Samples of every size 1..300: continuous, or rounded to a coarse grid
 * (ties), around a negative or positive loc. D+, D-, D and Kuiper's V from
 * nl_stats_ks_test and nl_stats_kuiper_test against the sup by counting.
 * Tolerance 2e-15: the same rank fractions (k / n, one division) less F(x)
 * at the same points; the library's F may differ from the one here by an
 * ulp or two (erfc's split), an ulp of values below 1 each: 4 ulps of 1,
 * 8.9e-16, doubled for V's sum. */
NL_TEST(statistics_are_the_sup_of_the_difference)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1933);
  double *x = malloc(300 * sizeof *x), worst = 0, worst_v = 0;
  long samples = 0;
  for (int n = 1; n <= 300; n++)
    for (int kind = 0; kind < 3; kind++) {
      nl_stats_dist_kind k = kind == 0 ? NL_DIST_UNIFORM : kind == 1 ? NL_DIST_NORM : NL_DIST_EXPON;
      double (*F)(double) = kind == 0 ? cdf_uniform : kind == 1 ? cdf_norm : cdf_expon;
      loc = 20 * gsl_rng_uniform(r) - 10;
      scale = 0.1 + 5 * gsl_rng_uniform(r);
      int ties = gsl_rng_uniform(r) < 0.3;
      for (int i = 0; i < n; i++) {
        double u = gsl_rng_uniform(r);
        double v = kind == 0 ? loc + scale * u
                 : kind == 1 ? loc + scale * gsl_ran_gaussian(r, 1.0)
                             : loc + scale * gsl_ran_exponential(r, 1.0);
        x[i] = ties ? loc + scale * round((v - loc) / scale * 8) / 8 : v;
        if (kind == 0 && x[i] >= loc + scale)   /* [a, b): rounding up past b */
          x[i] = loc;
      }
      nl_stats_dist dist;
      NL_CHECK(nl_stats_dist_init(&dist, k, loc, scale, NULL) == NL_OK);
      nl_stats_ks_result ks;
      nl_stats_kuiper_result ku;
      NL_CHECK(nl_stats_ks_test(x, (size_t)n, nl_stats_dist_cdf, &dist, &ks, NULL) == NL_OK);
      NL_CHECK(nl_stats_kuiper_test(x, (size_t)n, nl_stats_dist_cdf, &dist, &ku, NULL) == NL_OK);
      double dp, dm;
      ks_direct_one(x, (size_t)n, F, &dp, &dm);
      worst = fmax(worst, fmax(fabs(ks.d_plus - dp), fabs(ks.d_minus - dm)));
      worst = fmax(worst, fabs(ks.d - fmax(dp, dm)));
      worst_v = fmax(worst_v, fabs(ku.v - (dp + dm)));
      samples++;
    }
  printf("  %ld samples: max |D - sup| %.3g, max |V - (D+ + D-)| %.3g\n", samples, worst, worst_v);
  NL_CHECK(worst <= 2e-15 && worst_v <= 4e-15);
  free(x);
  gsl_rng_free(r);
}

/* Two samples of sizes 1..60 each, continuous or tied (integers 0..9 and
 * equal values across the samples): D+, D-, D of nl_stats_ks2_test, and its
 * p-value against the lattice walk at D's exact numerator. Statistics:
 * tolerance 0: D+ and D- subtract the same two quotients of counts; the
 * reported D is the lattice value num / g / lcm(n1, n2) (as scipy reports
 * it, g = gcd), one correctly rounded division of integers on both sides.
 * p: 1e-12 absolute: the walk sums n1 n2 probabilities in long double, the
 * library counts paths its own way (Hodges, Viehmann) in double. */
NL_TEST(two_sample_statistic_and_exact_p)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1958);
  double x[60], y[60], worst_p = 0;
  long bad = 0, pairs = 0;
  for (int t = 0; t < 3000; t++) {
    int n1 = 1 + (int)gsl_rng_uniform_int(r, 60), n2 = 1 + (int)gsl_rng_uniform_int(r, 60);
    int ties = t % 2;
    double shift = gsl_rng_uniform(r) < 0.5 ? 0 : 0.5 * gsl_rng_uniform(r);
    for (int i = 0; i < n1; i++)
      x[i] = ties ? (double)gsl_rng_uniform_int(r, 10) - 5 : gsl_ran_gaussian(r, 1.0);
    for (int i = 0; i < n2; i++)
      y[i] = ties ? (double)gsl_rng_uniform_int(r, 10) - 5 : gsl_ran_gaussian(r, 1.0) + shift;
    nl_stats_ks_result res;
    NL_CHECK(nl_stats_ks2_test(x, (size_t)n1, y, (size_t)n2, &res, NULL) == NL_OK);
    double dp, dm;
    long num, g = n1, h = n2;
    ks_direct_two(x, (size_t)n1, y, (size_t)n2, &dp, &dm, &num);
    while (h) {
      long m = g % h;
      g = h;
      h = m;
    }
    double lattice = (double)(num / g) / (double)((long)n1 * n2 / g);
    bad += res.d_plus != dp || res.d_minus != dm || res.d != lattice;
    double want = (double)ks2_paths_sf(n1, n2, num);
    worst_p = fmax(worst_p, fabs(res.p - want));
    pairs++;
  }
  printf("  %ld sample pairs: %ld statistics differ, max |p - lattice walk| %.3g\n", pairs, bad,
         worst_p);
  NL_CHECK(bad == 0 && worst_p <= 1e-12);
  gsl_rng_free(r);
}

/* The laws: nl_stats_smirnov_sf against Birnbaum-Tingey's sum at 6000
 * (n, d), n up to 1000 (relative 1e-11: positive terms in long double here;
 * in double there the powers (1 - d - j/n)^(n-j) magnify the rounding of
 * their base n - j times, ~n eps = 1.1e-13 at n = 1000, and sums of such
 * terms reach 1.1e-12 (n = 755); the library's claim against scipy is
 * 1e-10); nl_stats_ks_sf and
 * nl_stats_ks_cdf against Durbin's matrix at 4000 (n, d), n <= 30 and
 * n d < 10 (absolute 1e-13 on both tails: the matrix power in long double
 * carries about 1e-16 of the largest entries) and, for d >= 1/2 where the
 * two-sided tail is twice the one-sided exactly, against 2 Birnbaum-Tingey
 * (relative 1e-12, small tails included); nl_stats_kolmogorov_sf against
 * the series at 2000 lambda in (0.05, 6] (relative 1e-13: a few terms of
 * fast decay, or 1 minus the theta form below lambda = 1). */
NL_TEST(laws_of_d_match_their_definitions)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1951);
  double w_smirnov = 0, w_durbin = 0, w_two = 0, w_kolm = 0;
  for (int t = 0; t < 6000; t++) {
    int n = 1 + (int)gsl_rng_uniform_int(r, t % 10 == 0 ? 1000 : 200);
    double d = gsl_rng_uniform_pos(r);
    long double want = ks_birnbaum_tingey(n, d);
    long double err = nl_stats_smirnov_sf((size_t)n, d) - want;
    if (want > 1e-290)
      w_smirnov = fmax(w_smirnov, fabs((double)(err / want)));
  }
  for (int t = 0; t < 4000; t++) {
    int n = 1 + (int)gsl_rng_uniform_int(r, 30);
    double d = fmin(1.0, 10.0 / n) * gsl_rng_uniform_pos(r);
    long double cdf = ks_durbin_cdf(n, d);
    w_durbin = fmax(w_durbin, fabs((double)(nl_stats_ks_cdf((size_t)n, d, NULL) - cdf)));
    w_durbin = fmax(w_durbin, fabs((double)(nl_stats_ks_sf((size_t)n, d, NULL) - (1 - cdf))));
    double d2 = 0.5 + 0.5 * gsl_rng_uniform(r);
    long double two = 2 * ks_birnbaum_tingey(n, d2);
    if (two > 1e-290)
      w_two = fmax(w_two, fabs((double)((nl_stats_ks_sf((size_t)n, d2, NULL) - two) / two)));
  }
  for (int t = 0; t < 2000; t++) {
    double l = 0.05 + 5.95 * gsl_rng_uniform(r);
    long double want = ks_kolmogorov_sf(l);
    double err = fabs((double)(nl_stats_kolmogorov_sf(l) - want));
    w_kolm = fmax(w_kolm, err / (double)want);   /* want >= 2e-31 for lambda <= 6 */
  }
  printf("  smirnov relative %.3g; ks cdf/sf vs Durbin absolute %.3g; ks sf vs 2 BT relative"
         " %.3g; kolmogorov relative %.3g\n",
         w_smirnov, w_durbin, w_two, w_kolm);
  NL_CHECK(w_smirnov <= 1e-11);
  NL_CHECK(w_durbin <= 1e-13);
  NL_CHECK(w_two <= 1e-12);
  NL_CHECK(w_kolm <= 1e-13);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
