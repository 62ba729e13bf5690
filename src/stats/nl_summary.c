/* nl_summary.c - mean, sample sd and min of a sample, in the two named
 * roundings of nl_stats.h (GSL's running mean, or sums in order). */
#include "stats/nl_stats.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>

static double summed_mean(const double *x, size_t n)
{
  double s = 0;
  for (size_t i = 0; i < n; i++) s += x[i];
  return s / (double)n;
}

/* Two passes around the mean m: sqrt(sum (x_i - m)^2 / (n - 1)). */
static double summed_sd(const double *x, size_t n, double m)
{
  double ss = 0;
  for (size_t i = 0; i < n; i++) ss += (x[i] - m) * (x[i] - m);
  return n > 1 ? sqrt(ss / (double)(n - 1)) : 0;
}

double nl_stats_mean(const double *x, size_t n, nl_stats_rounding rounding)
{
  if (rounding == NL_STATS_SUMMED) return summed_mean(x, n);
  return gsl_stats_mean(x, 1, n);
}

double nl_stats_sd(const double *x, size_t n, nl_stats_rounding rounding)
{
  if (rounding == NL_STATS_SUMMED) return summed_sd(x, n, summed_mean(x, n));
  return n > 1 ? gsl_stats_sd(x, 1, n) : 0.0;
}

void nl_stats_mean_sd(const double *x, size_t n, nl_stats_rounding rounding, double *mean,
                      double *sd)
{
  *mean = nl_stats_mean(x, n, rounding);
  if (rounding == NL_STATS_SUMMED) *sd = summed_sd(x, n, *mean);
  else *sd = n > 1 ? gsl_stats_sd(x, 1, n) : 0.0;
}

nl_status nl_stats_mean_sd_checked(const double *x, size_t n, nl_stats_rounding rounding,
                                   double *mean, double *sd, nl_error *err)
{
  if (rounding != NL_STATS_RUNNING && rounding != NL_STATS_SUMMED)
    return nl_fail(err, NL_EINVAL, "rounding: %d is not running (0) or summed (1)", (int)rounding);
  if (n == 0) return nl_fail(err, NL_EINVAL, "sample: no values");
  nl_stats_mean_sd(x, n, rounding, mean, sd);
  return NL_OK;
}

double nl_stats_min(const double *x, size_t n)
{
  double m = x[0];
  for (size_t i = 1; i < n; i++) m = fmin(m, x[i]);
  return m;
}
