/* Tests of nl_summary.c: the RUNNING rounding is GSL's to the bit (GSL is
 * the reference), the SUMMED rounding is the two-pass formula in order to
 * the bit, and both agree with a long double computation to 1e-14
 * relative (they differ from each other only in rounding). */
#include "stats/nl_stats.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <string.h>

NL_TEST(mean_sd_in_both_roundings)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  const size_t sizes[] = {1, 2, 3, 10, 257, 5000};
  for (size_t si = 0; si < sizeof sizes / sizeof *sizes; si++) {
    size_t n = sizes[si];
    double x[5000];
    for (size_t i = 0; i < n; i++) x[i] = 1e3 + 7 * gsl_rng_uniform(r);   /* a large offset */
    long double s = 0, ss = 0;
    double sum = 0, dev = 0;
    for (size_t i = 0; i < n; i++) {
      s += x[i];
      sum += x[i];
    }
    double m_in_order = sum / (double)n;
    for (size_t i = 0; i < n; i++) {
      ss += ((long double)x[i] - s / n) * ((long double)x[i] - s / n);
      dev += (x[i] - m_in_order) * (x[i] - m_in_order);
    }
    double sd_in_order = n > 1 ? sqrt(dev / (double)(n - 1)) : 0;
    double m_ref = (double)(s / n), sd_ref = n > 1 ? (double)sqrtl(ss / (n - 1)) : 0;
    double m, sd;
    nl_stats_mean_sd(x, n, NL_STATS_RUNNING, &m, &sd);
    NL_CHECK(m == gsl_stats_mean(x, 1, n) && m == nl_stats_mean(x, n, NL_STATS_RUNNING));
    NL_CHECK(sd == (n > 1 ? gsl_stats_sd(x, 1, n) : 0));
    NL_CHECK(sd == nl_stats_sd(x, n, NL_STATS_RUNNING));
    NL_CHECK_NEAR(m, m_ref, 1e-14 * m_ref);
    NL_CHECK_NEAR(sd, sd_ref, 1e-9 * (sd_ref + 1));   /* cancellation: sd << mean */
    nl_stats_mean_sd(x, n, NL_STATS_SUMMED, &m, &sd);
    NL_CHECK(m == m_in_order && m == nl_stats_mean(x, n, NL_STATS_SUMMED));
    NL_CHECK(sd == sd_in_order && sd == nl_stats_sd(x, n, NL_STATS_SUMMED));
    NL_CHECK_NEAR(m, m_ref, 1e-14 * m_ref);
    NL_CHECK_NEAR(sd, sd_ref, 1e-9 * (sd_ref + 1));
  }
  const double v[] = {3, -1, NAN, 2};
  NL_CHECK(nl_stats_min(v, 4) == -1 && nl_stats_min(v, 1) == 3);
  double m, sd;
  nl_stats_mean_sd(v, 0, NL_STATS_SUMMED, &m, &sd);
  NL_CHECK(isnan(m) && sd == 0);
  nl_error err;
  m = sd = 7;
  NL_CHECK(nl_stats_mean_sd_checked(v, 0, NL_STATS_RUNNING, &m, &sd, &err) == NL_EINVAL);
  NL_CHECK(!strcmp(err.msg, "sample: no values") && m == 7 && sd == 7);
  NL_CHECK(nl_stats_mean_sd_checked(v, 2, (nl_stats_rounding)2, &m, &sd, &err) == NL_EINVAL);
  NL_CHECK(nl_stats_mean_sd_checked(v, 2, NL_STATS_SUMMED, &m, &sd, &err) == NL_OK && m == 1 && sd == sqrt(8));
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
