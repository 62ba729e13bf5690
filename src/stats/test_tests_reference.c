/* test_tests_reference.c - chi-square, Welch and F tests against their
 * statistics written out here and their tails from the textbook series and
 * continued fractions in long double (tests/reference/special_tails.c), at
 * thousands of inputs; the library takes its tails from GSL.
 *
 * Inputs: 3000 chi-square tables (k = 2..60 cells, expected counts
 * positive and unequal, observed counts near or far from them, so p from 1
 * down to 1e-300), 3000 Welch and 3000 F tests (n 2..200 a side, sds over
 * four decades, means near and far apart). Tolerances: chi2 1e-13 relative
 * (k terms summed in another order); t, df inside the p-values; p 1e-10
 * relative where p > 1e-290 (GSL's incomplete gamma and beta in double
 * lose a few digits to the exponent of the leading factor, exp(a log x -
 * x - lgamma a) with terms up to ~1e3: ~1e3 eps; measured in the output),
 * 1e-300 absolute below.
 *
 * Welch below p = 1e-8: 1e-5 relative. gsl_cdf_tdist_Q takes a
 * Cornish-Fisher expansion for t^2 < 10 df, whose relative error grows into
 * the tail: 1e-10 at p = 3e-9, 3e-10 at 1e-24, 6.6e-7 at 1e-30 and
 * 5.4e-7 at 1e-106 here (checked against mpmath's betainc at 40 digits).
 * Above 1e-8 it holds 1.6e-11.
 */
#include "stats/nl_stats.h"
#include "nl_test.h"
#include "reference/special_tails.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>

static double worst[5];   /* chi2, chisq p, welch p (p >= 1e-8), ftest p, welch p below */

static void note_p(int which, double got, long double want)
{
  double err = fabs((double)(got - want));
  if (want > 1e-290L)
    err /= (double)want;
  else
    err = err > 1e-300 ? 1 : 0;
  worst[which] = fmax(worst[which], err);
}

NL_TEST(p_values_match_the_textbook_tails)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 1900);
  double obs[60], expd[60];
  for (int t = 0; t < 3000; t++) {
    size_t k = 2 + gsl_rng_uniform_int(r, 59);
    double spread = t % 3 == 0 ? 0.1 : t % 3 == 1 ? 1 : 4;
    long double chi2 = 0;
    for (size_t i = 0; i < k; i++) {
      expd[i] = 1 + 200 * gsl_rng_uniform(r);
      obs[i] = fmax(0, round(expd[i] + spread * sqrt(expd[i]) * gsl_ran_gaussian(r, 1.0)));
      chi2 += ((long double)obs[i] - expd[i]) * ((long double)obs[i] - expd[i]) / expd[i];
    }
    nl_stats_chisq_result res;
    NL_CHECK(nl_stats_chisq_test(obs, expd, k, &res, NULL) == NL_OK);
    worst[0] = fmax(worst[0], fabs((double)((res.chi2 - chi2) / chi2)));
    note_p(1, res.p, tail_gamma_q((long double)(k - 1) / 2, chi2 / 2));
  }
  for (int t = 0; t < 3000; t++) {
    size_t n1 = 2 + gsl_rng_uniform_int(r, 199), n2 = 2 + gsl_rng_uniform_int(r, 199);
    double s1 = pow(10, 4 * gsl_rng_uniform(r) - 2), s2 = s1 * pow(10, 2 * gsl_rng_uniform(r) - 1);
    double m1 = gsl_ran_gaussian(r, 1.0), m2 = m1 + gsl_ran_gaussian(r, 1.0) * (s1 + s2)
                                                   * (t % 2 ? 0.1 : 2);
    double p;
    NL_CHECK(nl_stats_welch_p(m1, s1, n1, m2, s2, n2, &p, NULL) == NL_OK);
    long double v1 = (long double)s1 * s1 / n1, v2 = (long double)s2 * s2 / n2;
    long double tt = fabsl((long double)m2 - m1) / sqrtl(v1 + v2);
    long double df = (v1 + v2) * (v1 + v2) / (v1 * v1 / (n1 - 1) + v2 * v2 / (n2 - 1));
    long double wp = tail_beta_i(df / 2, 0.5L, df / (df + tt * tt));
    note_p(wp >= 1e-8L ? 2 : 4, p, wp);
    NL_CHECK(nl_stats_ftest_p(s1, n1, s2, n2, &p, NULL) == NL_OK);
    long double f = (long double)s2 * s2 / ((long double)s1 * s1), d1 = n2 - 1, d2 = n1 - 1;
    long double cdf = tail_beta_i(d1 / 2, d2 / 2, d1 * f / (d1 * f + d2));
    long double sf = tail_beta_i(d2 / 2, d1 / 2, d2 / (d1 * f + d2));
    long double want = 2 * fminl(cdf, sf);
    note_p(3, p, want > 1 ? 1 : want);
  }
  printf("  chi2 relative %.3g; p relative: chi-square %.3g, Welch %.3g (p >= 1e-8; below:"
         " %.3g), F %.3g\n", worst[0], worst[1], worst[2], worst[4], worst[3]);
  NL_CHECK(worst[0] <= 1e-13);
  for (int q = 1; q < 4; q++)
    NL_CHECK(worst[q] <= 1e-10);
  NL_CHECK(worst[4] <= 1e-5);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
