/* Two-sample tests from summaries (mean, sd, n): Welch's t-test and the
 * F-test of equal variances. See nl_stats.h. The regression check
 * (nl_harness_check.c) compares means and spreads over seeds with these. */
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <math.h>

static nl_status summary_ok(const char *what, double sd, size_t n, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "%s: n = %zu, need >= 2 for a spread", what, n);
  if (!(sd >= 0) || isinf(sd)) return nl_fail(err, NL_EINVAL, "%s: sd %g is not finite and >= 0", what, sd);
  return NL_OK;
}

nl_status nl_stats_welch_p(double m1, double s1, size_t n1, double m2, double s2, size_t n2,
                           double *p, nl_error *err)
{
  nl_status st;
  if ((st = summary_ok("welch", s1, n1, err)) || (st = summary_ok("welch", s2, n2, err))) return st;
  if (!isfinite(m1) || !isfinite(m2)) return nl_fail(err, NL_EINVAL, "welch: means must be finite");
  if (s1 == 0 && s2 == 0) return nl_fail(err, NL_EINVAL, "welch: both sds are 0, no test (compare the means)");
  /* The standard error of each mean, and the Welch-Satterthwaite degrees of
   * freedom, exactly as scipy.stats.ttest_ind_from_stats(equal_var=False). */
  double v1 = s1 * s1 / (double)n1, v2 = s2 * s2 / (double)n2;
  double t = fabs(m2 - m1) / sqrt(v1 + v2);
  double df = (v1 + v2) * (v1 + v2) / (v1 * v1 / (double)(n1 - 1) + v2 * v2 / (double)(n2 - 1));
  *p = 2 * gsl_cdf_tdist_Q(t, df);
  return NL_OK;
}

nl_status nl_stats_ftest_p(double s1, size_t n1, double s2, size_t n2, double *p, nl_error *err)
{
  nl_status st;
  if ((st = summary_ok("ftest", s1, n1, err)) || (st = summary_ok("ftest", s2, n2, err))) return st;
  if (s1 == 0 && s2 == 0) return nl_fail(err, NL_EINVAL, "ftest: both sds are 0, no test");
  if (s1 == 0 || s2 == 0) { *p = 0; return NL_OK; }   /* one spread vanished, the other did not */
  /* F = s2^2 / s1^2 with (n2 - 1, n1 - 1) degrees of freedom; two-sided:
   * twice the smaller tail, capped at 1. */
  double f = (s2 * s2) / (s1 * s1);
  double q = 2 * fmin(gsl_cdf_fdist_P(f, (double)(n2 - 1), (double)(n1 - 1)),
                      gsl_cdf_fdist_Q(f, (double)(n2 - 1), (double)(n1 - 1)));
  *p = fmin(q, 1.0);
  return NL_OK;
}
