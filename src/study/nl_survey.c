/* The surveys behind S1-S3 (nl_study.h): harness-side, since they write
 * tables and images; the noise module itself depends on base only. */
#include "study/nl_study.h"
#include "basis/nl_basis.h"
#include "spectrum/nl_spectrum.h"

#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* How axis-aligned the octaves of a sum are on their slices: for each
 * octave l with amp_l != 0 alone, noise(f_l p) on the plane z, the fraction
 * of about npts points whose gradient lies within 2 degrees of the x or y
 * axis (|g_y| <= tan(2 deg) |g_x| or the reverse). Returns the fraction
 * pooled over those octaves; *worst gets the largest single octave's. The
 * octaves are taken alone because a lattice-plane octave's creases hide in
 * the sum's gradient (mixed with the other octaves') yet show as straight
 * lines in the picture, in turbulence's folds most of all. The points run
 * along rows at random y and start (from `seed`) over 64 windows (the whole
 * 256-cell period of improved noise for the default window: many
 * independent cells), spaced by the golden ratio times the pixel, an
 * irrational multiple of every octave's period, so they fall everywhere in
 * the cells (pixel centres may all share one position in the cells of an
 * octave above the pixel rate). Forward differences over h, a millionth
 * of the octave's period: the field's own gradient. */
static double axis_fraction(const nl_noise_basis *b, const nl_noise_octaves *o,
                            const nl_noise_window *win, size_t npts, unsigned long seed,
                            double *worst)
{
  double tol = tan(2.0 * NL_PI / 180.0), dx = win->size / win->w * 1.6180339887498949;
  size_t w = (size_t)win->w, rows = (npts + w - 1) / w, hit = 0, n = 0;
  double *v = nl_xmalloc(4 * w * sizeof *v);
  gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
  *worst = 0;
  for (int l = 0; l < o->n; l++) {
    if (o->amp[l] == 0) continue; /* not in the picture */
    nl_noise_octaves one = nl_noise_octaves_fbm(1, 1.0, 1.0);
    one.freq[0] = o->freq[l];
    double h = 1e-6 / fabs(o->freq[l]);
    size_t hl = 0, nl = 0;
    gsl_rng_set(g, nl_seed_stream(seed, "survey.axis", (unsigned long)l));
    for (size_t r = 0; r < rows; r++) {
      double x = win->x0 + 64 * win->size * gsl_rng_uniform(g);
      double y = win->y0 + 64 * win->size * gsl_rng_uniform(g);
      nl_noise_fractal_row(b, &one, x, dx, y, win->z, w, v, v + 3 * w);
      nl_noise_fractal_row(b, &one, x + h, dx, y, win->z, w, v + w, v + 3 * w);
      nl_noise_fractal_row(b, &one, x, dx, y + h, win->z, w, v + 2 * w, v + 3 * w);
      for (size_t k = 0; k < w; k++) {
        double gx = fabs(v[w + k] - v[k]), gy = fabs(v[2 * w + k] - v[k]);
        if (gx == 0 && gy == 0) continue; /* no direction */
        nl++;
        hl += gy <= tol * gx || gx <= tol * gy;
      }
    }
    if (nl && (double)hl / nl > *worst) *worst = (double)hl / nl;
    hit += hl;
    n += nl;
  }
  free(v);
  gsl_rng_free(g);
  return n ? (double)hit / n : NAN;
}

/* The sd the sum would have if its octaves were uncorrelated, each with
 * the variance it has alone on this window: sqrt(sum amp_l^2 var_l), var_l
 * the variance of octave l's raster (of |noise| for turbulence). Against
 * the sum's own sd it isolates the octaves' correlation; against the lone
 * first octave's sd, what sampling does to each octave's variance (octaves
 * wider than the window, octaves above the pixel rate). */
static double separate_sd(const nl_noise_basis *b, const nl_noise_octaves *o,
                          const nl_noise_window *win, double *v)
{
  size_t n = (size_t)win->w * win->h;
  double var = 0;
  for (int l = 0; l < o->n; l++) {
    if (o->amp[l] == 0) continue;
    nl_noise_octaves one = nl_noise_octaves_fbm(1, 1.0, 1.0);
    one.freq[0] = o->freq[l];
    one.turbulence = o->turbulence;
    nl_noise_fractal_grid(b, &one, win, v);
    var += o->amp[l] * o->amp[l] * gsl_stats_variance(v, 1, n);
  }
  return sqrt(var);
}

/* Seed k's statistics of the sum rendered into v, which keeps the sum (the
 * first seed's is the picture the montage shows); scratch holds the
 * octaves rendered alone for separate_sd. */
static void one_seed(nl_study_survey *s, nl_study_basis_kind kind, const nl_noise_octaves *o, const nl_noise_window *win,
                     unsigned long seed, int k, double *v, double *scratch)
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
  /* The window's side passed nl_harness_param_fft_size (nl_study_window);
   * were it refused all the same, the power is NaN, not minutes. */
  if (nl_spectrum_radial(v, win->w, win->h, s->nbins, f, s->power + (size_t)k * s->nbins, NULL))
    for (int q = 0; q < s->nbins; q++) s->power[(size_t)k * s->nbins + q] = NAN;
  free(f);
  s->axis[k] = axis_fraction(&b->noise, o, win, NL_STUDY_AXIS_POINTS(win->w, win->h), seed,
                             &s->axis_worst[k]);
  s->sd_sep[k] = o->n == 1 ? s->sd[k] : separate_sd(&b->noise, o, win, scratch);
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
  s->axis = nl_xmalloc((size_t)nseeds * sizeof *s->axis);
  s->axis_worst = nl_xmalloc((size_t)nseeds * sizeof *s->axis_worst);
  s->sd_sep = nl_xmalloc((size_t)nseeds * sizeof *s->sd_sep);
  s->freq = nl_xmalloc((size_t)s->nbins * sizeof *s->freq);
  s->power = nl_xmalloc((size_t)nseeds * s->nbins * sizeof *s->power);
  s->first = nl_xmalloc((size_t)win->w * win->h * sizeof *s->first);
  double *v = nl_xmalloc(2 * (size_t)win->w * win->h * sizeof *v);
  for (int k = 0; k < nseeds; k++)
    one_seed(s, kind, o, win, nl_seed_replicate(seed0, k), k, k == 0 ? s->first : v,
             v + (size_t)win->w * win->h);
  /* nl_spectrum_radial bins in cycles per pixel; a pixel is size/w units. */
  for (int b = 0; b < s->nbins; b++) s->freq[b] = (b + 0.5) * 0.5 / s->nbins * win->w / win->size;
  free(v);
  return s;
}

void nl_study_survey_free(nl_study_survey *s)
{
  if (!s) return;
  free(s->mean);
  free(s->sd);
  free(s->min);
  free(s->max);
  free(s->axis);
  free(s->axis_worst);
  free(s->sd_sep);
  free(s->freq);
  free(s->power);
  free(s->first);
  free(s);
}

static nl_table *dist_table(void)
{
  const char *cols[] = {"setting", "octaves", "gain", "lacunarity", "mean", "mean_sd", "sd", "sd_sd",
                        "min", "max", "max_abs", "bound", "max_abs_over_bound", "axis_frac",
                        "axis_frac_sd", "axis_frac_worst", "axis_frac_iso"};
  return nl_table_alloc(17, cols);
}

static void dist_row(nl_table *t, const nl_study_setting *st, const nl_study_survey *s)
{
  size_t n = (size_t)s->nseeds;
  const nl_noise_octaves *o = &st->oct;
  double m = gsl_stats_mean(s->mean, 1, n), sd = gsl_stats_mean(s->sd, 1, n);
  double msd = n > 1 ? gsl_stats_sd(s->mean, 1, n) : 0, sdsd = n > 1 ? gsl_stats_sd(s->sd, 1, n) : 0;
  double mx = 0;
  for (size_t k = 0; k < n; k++) mx = fmax(mx, fmax(fabs(s->min[k]), fabs(s->max[k])));
  double ax = gsl_stats_mean(s->axis, 1, n), axsd = n > 1 ? gsl_stats_sd(s->axis, 1, n) : 0;
  nl_table_append(t, "siddddddddddddddd", st->label, o->n, st->gain, st->lacunarity, m, msd, sd,
                  sdsd, gsl_stats_mean(s->min, 1, n), gsl_stats_mean(s->max, 1, n), mx, s->bound,
                  mx / s->bound, ax, axsd, gsl_stats_mean(s->axis_worst, 1, n), 16.0 / 360.0);
}

void nl_study_survey_series(nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                            const nl_noise_window *win, unsigned long seed0, int nseeds,
                            nl_table **dist, nl_table **spectrum, nl_image **panels,
                            nl_table **per_seed)
{
  nl_table *dt = dist_table(), *sp = NULL;
  const char *pcols[] = {"setting", "seed", "mean", "sd", "sd_sep", "axis_frac"};
  nl_table *ps = nl_table_alloc(6, pcols);
  for (int i = 0; i < n; i++) {
    nl_study_survey *s = nl_study_survey_run(kind, &settings[i].oct, win, seed0, nseeds);
    dist_row(dt, &settings[i], s);
    for (int k = 0; k < nseeds; k++)
      nl_table_append(ps, "sddddd", settings[i].label, (double)nl_seed_replicate(seed0, k),
                      s->mean[k], s->sd[k], s->sd_sep[k], s->axis[k]);
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
  if (per_seed) *per_seed = ps; else nl_table_free(ps);
  if (spectrum) *spectrum = sp; else nl_table_free(sp);
}
