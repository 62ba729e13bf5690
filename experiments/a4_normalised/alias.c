/* alias.c - A4's aliased energy (alias.h). */
#include "alias.h"
#include "line.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

nl_status a4_alias_energy(const nl_noise_perm3 *p, double f, double length, double rate,
                          double nyquist, double *e_over_t, nl_error *err)
{
  size_t n;
  double *x = a4_line_sample(p, f, length, rate, &n);
  double frac, mean, sigma;
  nl_status rc = nl_bounds_psd1_fraction_above(x, n, rate, nyquist, &frac, err);
  nl_bounds_moments(x, n, &mean, &sigma);
  free(x);
  /* Parseval: the PSD without its DC bin sums to the variance; the stored
   * value (noise + 1) / 2 has a quarter of it. */
  if (!rc) *e_over_t = frac * 0.25 * sigma * sigma / NL_BOUNDS_T;
  return rc;
}

void a4_t_test(const double *x, int n, double mu, double *p_below, double *p_above)
{
  double m = gsl_stats_mean(x, 1, (size_t)n);
  double sd = n > 1 ? gsl_stats_sd_m(x, 1, (size_t)n, m) : 0.0;
  if (n < 2 || sd == 0.0) {
    *p_below = m < mu ? 0.0 : m > mu ? 1.0 : 0.5;
    *p_above = m > mu ? 0.0 : m < mu ? 1.0 : 0.5;
    if (n < 2) *p_below = *p_above = 0.5;
    return;
  }
  double t = (m - mu) / (sd / sqrt((double)n));
  *p_below = gsl_cdf_tdist_P(t, n - 1.0);
  *p_above = gsl_cdf_tdist_Q(t, n - 1.0);
}

nl_table *a4_energy_table(double e[3][64], int seeds, double f_ours, double f_paper)
{
  const char *cols[] = { "signal",  "divisor", "energy_over_t", "energy_over_t_sd",
                         "p_below", "p_above", "seeds" };
  const char *name[3] = { "noise(x)", "noise(x / F_sup), ours", "noise(x / F_sup), paper's" };
  const double div[3] = { 1.0, f_ours, f_paper };
  nl_table *t = nl_table_alloc(7, cols);
  for (int v = 0; v < 3; v++) {
    double lo, hi;
    a4_t_test(e[v], seeds, 1.0, &lo, &hi);
    double sd = seeds > 1 ? gsl_stats_sd(e[v], 1, (size_t)seeds) : 0.0;
    nl_table_append(t, "sdddddi", name[v], div[v], gsl_stats_mean(e[v], 1, (size_t)seeds), sd, lo,
                    hi, seeds);
  }
  return t;
}
