/* alias.c - A4's aliased energy (alias.h). */
#include "alias.h"
#include "line.h"
#include "noise/nl_noise.h"
#include "spectrum/nl_spectrum.h"

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

nl_status a4_alias_energy2(const nl_noise_perm3 *p, double f, double extent, double rate,
                           double nyquist, double *e_over_t, nl_error *err)
{
  int n = (int)llround(extent * rate);
  nl_status rc = nl_spectrum_check_size(n, n, err);
  if (rc) return rc;
  nl_noise_basis b = nl_noise_basis_perm3(p);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  o.freq[0] = f;
  nl_noise_window w = { 0, 0, 0.5, extent, n, n };
  size_t nn = (size_t)n * (size_t)n;
  double *v = nl_xmalloc(nn * sizeof *v), *P = nl_xmalloc(nn * sizeof *P);
  nl_noise_fractal_grid(&b, &o, &w, v);
  for (size_t k = 0; k < nn; k++) v[k] = 0.5 * (v[k] + 1.0); /* the stored value */
  nl_spectrum_hann2(v, n, n, v);
  if (nl_spectrum_power2(v, n, n, P, err)) {   /* checked above */
    free(v);
    free(P);
    return NL_EINVAL;
  }
  double above = 0;
  for (int y = 0; y < n; y++) {
    double fy = fabs(nl_spectrum_freq(y, n)) * rate;
    for (int x = 0; x < n; x++) {
      double fx = fabs(nl_spectrum_freq(x, n)) * rate;
      if (fx > nyquist || fy > nyquist) above += P[(size_t)y * n + x];
    }
  }
  free(v);
  free(P);
  *e_over_t = above / NL_BOUNDS_T;
  return NL_OK;
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
