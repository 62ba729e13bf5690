/* fold.c - S2: one octave of noise against its absolute value, the DC term
 * and the power above the octave's band, from exact 2D power spectra. */
#include "fold.h"

#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

/* dc = P[0] / sum P (Parseval: sum P = mean(v^2)); above = the share of the
 * non-DC power at |k| > cut cycles per unit (k in cycles per unit: index
 * over the window's side, folded to [-w/2, w/2)). */
static void shares(const double *v, const nl_noise_window *win, double cut, double *P, double *dc,
                   double *above)
{
  int w = win->w, h = win->h;
  /* The window's side passed nl_harness_param_fft_size (nl_study_window). */
  if (nl_spectrum_power2(v, w, h, P, NULL)) {
    *dc = *above = NAN;
    return;
  }
  double total = 0, hi = 0;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      double p = P[(size_t)y * w + x];
      if (x == 0 && y == 0) continue;
      double ku = (x < w / 2 ? x : x - w) / win->size, kv = (y < h / 2 ? y : y - h) / win->size;
      total += p;
      if (sqrt(ku * ku + kv * kv) > cut) hi += p;
    }
  *dc = P[0] / (P[0] + total);
  *above = hi / total;
}

nl_table *s2_fold_table(const nl_noise_window *win, unsigned long seed0, int nseeds, double cut)
{
  const char *cols[] = { "field",      "mean",          "mean_sd", "dc_frac",
                         "above_frac", "above_frac_sd", "seeds" };
  nl_table *t = nl_table_alloc(7, cols);
  size_t n = (size_t)win->w * win->h;
  double *v = nl_xmalloc(n * sizeof *v), *P = nl_xmalloc(n * sizeof *P);
  double *m = nl_xmalloc(3 * (size_t)nseeds * sizeof *m), *dc = m + nseeds, *ab = dc + nseeds;
  /* rows: noise, |noise|, and noise again on the next nseeds seeds (the
   * unfolded baseline a comparison of the first two is checked against) */
  for (int row = 0; row < 3; row++) {
    int fold = row == 1;
    for (int k = 0; k < nseeds; k++) {
      nl_noise_perm3 p;
      nl_noise_perm3_seed(&p, nl_seed_replicate(seed0, row == 2 ? nseeds + k : k));
      nl_noise_basis b = nl_noise_basis_perm3(&p);
      nl_noise_octaves o = nl_noise_octaves_fractal(1);
      o.turbulence = fold;
      nl_noise_fractal_grid(&b, &o, win, v);
      m[k] = gsl_stats_mean(v, 1, n);
      shares(v, win, cut, P, &dc[k], &ab[k]);
    }
    double msd = nseeds > 1 ? gsl_stats_sd(m, 1, nseeds) : 0;
    double asd = nseeds > 1 ? gsl_stats_sd(ab, 1, nseeds) : 0;
    nl_table_append(t, "sdddddi", row == 0 ? "noise" : row == 1 ? "|noise|" : "noise, other seeds",
                    gsl_stats_mean(m, 1, nseeds), msd, gsl_stats_mean(dc, 1, nseeds),
                    gsl_stats_mean(ab, 1, nseeds), asd, nseeds);
  }
  free(v);
  free(P);
  free(m);
  return t;
}
