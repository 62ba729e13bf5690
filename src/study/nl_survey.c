/* The surveys behind S1-S3 (nl_study.h): harness-side, since they write
 * tables and images; the noise module itself depends on base only. */
#include "study/nl_study.h"
#include "basis/nl_basis.h"
#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void one_seed(nl_study_survey *s, nl_study_basis_kind kind, const nl_noise_octaves *o, const nl_noise_window *win,
                     unsigned long seed, int k, double *v)
{
  nl_basis *b;
  nl_error err;
  if (nl_basis_make(kind, NULL, seed, &b, &err)) {   /* kind is a name in the code, not input */
    fprintf(stderr, "noiselab: survey: %s\n", err.msg);
    abort();
  }
  nl_noise_fractal_grid(&b->noise, o, win, v);
  size_t n = (size_t)win->w * win->h;
  s->mean[k] = gsl_stats_mean(v, 1, n);
  s->sd[k] = gsl_stats_sd_m(v, 1, n, s->mean[k]);
  gsl_stats_minmax(&s->min[k], &s->max[k], v, 1, n);
  double *f = nl_xmalloc((size_t)s->nbins * sizeof *f);
  nl_spectrum_radial(v, win->w, win->h, s->nbins, f, s->power + (size_t)k * s->nbins);
  free(f);
  s->bound = nl_noise_octaves_bound(o, b->noise.bound);
  nl_basis_free(b);
}

nl_study_survey *nl_study_survey_run(nl_study_basis_kind kind, const nl_noise_octaves *o, const nl_noise_window *win,
                                     unsigned long seed0, int nseeds)
{
  nl_study_survey *s = nl_xcalloc(1, sizeof *s);
  s->nseeds = nseeds;
  s->w = win->w;
  s->h = win->h;
  s->nbins = (win->w < win->h ? win->w : win->h) / 2;
  s->mean = nl_xmalloc((size_t)nseeds * sizeof *s->mean);
  s->sd = nl_xmalloc((size_t)nseeds * sizeof *s->sd);
  s->min = nl_xmalloc((size_t)nseeds * sizeof *s->min);
  s->max = nl_xmalloc((size_t)nseeds * sizeof *s->max);
  s->freq = nl_xmalloc((size_t)s->nbins * sizeof *s->freq);
  s->power = nl_xmalloc((size_t)nseeds * s->nbins * sizeof *s->power);
  s->first = nl_xmalloc((size_t)win->w * win->h * sizeof *s->first);
  double *v = nl_xmalloc((size_t)win->w * win->h * sizeof *v);
  for (int k = 0; k < nseeds; k++)
    one_seed(s, kind, o, win, nl_seed_replicate(seed0, k), k, k == 0 ? s->first : v);
  /* nl_spectrum_radial bins in cycles per pixel; a pixel is size/w units. */
  for (int b = 0; b < s->nbins; b++) s->freq[b] = (b + 0.5) * 0.5 / s->nbins * win->w / win->size;
  free(v);
  return s;
}

void nl_study_survey_free(nl_study_survey *s)
{
  if (!s) return;
  free(s->mean); free(s->sd); free(s->min); free(s->max);
  free(s->freq); free(s->power); free(s->first); free(s);
}

static nl_table *dist_table(void)
{
  const char *cols[] = {"setting", "octaves", "gain", "lacunarity", "mean", "mean_sd", "sd", "sd_sd",
                        "min", "max", "max_abs", "bound", "max_abs_over_bound"};
  return nl_table_alloc(13, cols);
}

static void dist_row(nl_table *t, const nl_study_setting *st, const nl_study_survey *s)
{
  size_t n = (size_t)s->nseeds;
  const nl_noise_octaves *o = &st->oct;
  double m = gsl_stats_mean(s->mean, 1, n), sd = gsl_stats_mean(s->sd, 1, n);
  double msd = n > 1 ? gsl_stats_sd(s->mean, 1, n) : 0, sdsd = n > 1 ? gsl_stats_sd(s->sd, 1, n) : 0;
  double mx = 0;
  for (size_t k = 0; k < n; k++) mx = fmax(mx, fmax(fabs(s->min[k]), fabs(s->max[k])));
  nl_table_append(t, "siddddddddddd", st->label, o->n, st->gain, st->lacunarity, m, msd, sd, sdsd,
                  gsl_stats_mean(s->min, 1, n), gsl_stats_mean(s->max, 1, n), mx, s->bound, mx / s->bound);
}

void nl_study_survey_series(nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                            const nl_noise_window *win, unsigned long seed0, int nseeds,
                            nl_table **dist, nl_table **spectrum, nl_image **panels)
{
  nl_table *dt = dist_table(), *sp = NULL;
  for (int i = 0; i < n; i++) {
    nl_study_survey *s = nl_study_survey_run(kind, &settings[i].oct, win, seed0, nseeds);
    dist_row(dt, &settings[i], s);
    if (!sp) {
      const char **cols = nl_xmalloc((size_t)(n + 1) * sizeof *cols);
      cols[0] = "freq";
      for (int k = 0; k < n; k++) cols[k + 1] = settings[k].label;
      sp = nl_table_alloc((size_t)n + 1, cols);
      free(cols);
      for (int b = 0; b < s->nbins; b++) nl_table_set(sp, nl_table_append_empty(sp), "freq", s->freq[b]);
    }
    for (int b = 0; b < s->nbins; b++) {
      double p = 0;
      for (int k = 0; k < nseeds; k++) p += s->power[(size_t)k * s->nbins + b] / nseeds;
      nl_table_set(sp, (size_t)b, settings[i].label, p);
    }
    if (panels) {
      double m = s->mean[0], sd = s->sd[0] > 0 ? s->sd[0] : 1;
      panels[i] = nl_image_from_values(s->first, win->w, win->h, m - 3 * sd, m + 3 * sd);
    }
    nl_study_survey_free(s);
  }
  if (dist) *dist = dt; else nl_table_free(dt);
  if (spectrum) *spectrum = sp; else nl_table_free(sp);
}
