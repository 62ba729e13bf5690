#include "study/nl_study.h"

#include "basis/nl_basis.h"
#include "spectrum/nl_spectrum.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put(const char *prefix, const char *what, char *buf, size_t n)
{
  snprintf(buf, n, "%s_%s", prefix, what);
}

/* How far the series' octaves are from the lattice-plane creases, from the
 * axis_frac columns of dist (nl_study_survey_series). */
static void slice_text(nl_harness *r, const nl_table *dist, const nl_noise_window *win)
{
  size_t top = 0;
  double worst = 0;
  for (size_t i = 0; i < dist->nrows; i++) {
    if (nl_table_value(dist, i, "axis_frac") > nl_table_value(dist, top, "axis_frac")) top = i;
    worst = fmax(worst, nl_table_value(dist, i, "axis_frac_worst"));
  }
  double ax = nl_table_value(dist, top, "axis_frac");
  double iso = nl_table_value(dist, top, "axis_frac_iso");
  nl_harness_text(r,
                  "**Slice.** Each octave of frequency f samples the plane z f = %g f. The "
                  "gradients of the octaves, each alone on its plane, lie within 2 degrees of "
                  "the x or y axis at a fraction %.4f of points at most (axis_frac, %s; the "
                  "worst single octave of any setting %.4f) against %.4f for an isotropic "
                  "field: %.2f times. An octave on a lattice plane (z f an integer) would show "
                  "straight axis-aligned creases and raise this fraction (run with --set "
                  "z=0.5).\n",
                  win->z, ax, nl_table_text(dist, top, "setting"), worst, iso, ax / iso);
}

nl_table *nl_study_series(nl_harness *r, const char *prefix, const char *title,
                          nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                          const nl_noise_window *win, nl_table **per_seed)
{
  nl_table *dist, *spec, *seeds;
  nl_image **panels = nl_xcalloc((size_t)n, sizeof *panels);
  const char **labels = nl_xcalloc((size_t)n, sizeof *labels);
  for (int i = 0; i < n; i++) labels[i] = settings[i].label;
  nl_study_survey_series(kind, settings, n, win, nl_harness_seed(r), nl_harness_seeds(r), &dist,
                         &spec, panels, &seeds);
  nl_image *m = nl_image_montage((const nl_image *const *)panels, labels, n, n, title);
  char f[256], cap[512];
  put(prefix, "panels.png", f, sizeof f);
  nl_harness_write_image(r, m, f);
  snprintf(cap, sizeof cap, "%s (%d x %d, each panel from mean - 3 sd to mean + 3 sd)", title,
           win->w, win->h);
  nl_harness_figure(r, f, cap);
  put(prefix, "distribution.tsv", f, sizeof f);
  nl_harness_write_table(r, dist, f);
  snprintf(cap, sizeof cap,
           "Values over %d seeds (%s): mean and sd of the per-seed mean and sd, "
           "mean min and max, largest |value| seen against the analytic bound",
           nl_harness_seeds(r), f);
  nl_harness_report_table(r, dist, cap, 4);
  slice_text(r, dist, win);
  put(prefix, "spectrum.tsv", f, sizeof f);
  nl_harness_write_table(r, spec, f);
  put(prefix, "seeds.tsv", f, sizeof f);
  nl_harness_write_table(r, seeds, f);
  if (per_seed)
    *per_seed = seeds;
  else
    nl_table_free(seeds);
  /* Regression rules (scripts/noiselab check): mean and sd are means over
   * seeds with their spreads beside them, compared as statistics so that a
   * new random stream passes and a shift fails. Everything else, the
   * spectrum included, is exact for a seed: GSL's FFT has no CPU-dependent
   * plan, and no value moved over the CPU configurations of
   * bench/blas-spread.sh (the experiment's nl_harness_check_measured). */
  char dname[256];
  put(prefix, "distribution.tsv", dname, sizeof dname);
  nl_harness_check(r, dname, "mean", "welch mean_sd 1e-3");
  nl_harness_check(r, dname, "sd", "welch sd_sd 1e-3");
  nl_harness_check(r, dname, "mean_sd", "ftest 1e-3");
  nl_harness_check(r, dname, "sd_sd", "ftest 1e-3");
  put(prefix, "spectrum.png", f, sizeof f);
  nl_harness_figure(r, f, "Radially averaged power spectrum, mean over seeds");
  for (int i = 0; i < n; i++) nl_image_free(panels[i]);
  free(panels); free(labels);
  nl_image_free(m);
  nl_table_free(spec);
  return dist;
}

/* Fills settings[i] for octave counts oct[i] of Shaffer's fractal sum (gain
 * 1/2, lacunarity 2), optionally turbulent; labels "(a) 1 octave" are
 * written into labels[i] (32 bytes each). */
static void octave_settings(const int *oct, int n, int turbulence, nl_study_setting *settings,
                            char (*labels)[32])
{
  for (int i = 0; i < n; i++) {
    snprintf(labels[i], 32, "(%c) %d octave%s", 'a' + i, oct[i], oct[i] > 1 ? "s" : "");
    settings[i].label = labels[i];
    settings[i].oct = nl_noise_octaves_fractal(oct[i]);
    settings[i].oct.turbulence = turbulence;
    settings[i].gain = 0.5;
    settings[i].lacunarity = 2;
  }
}

nl_noise_window nl_study_window(nl_harness *r)
{
  int size = (int)nl_harness_param_fft_size(r, "size", nl_harness_quick(r) ? 128 : 512, 16, 4096,
                                       "image side in pixels of each survey slice (quick 128)");
  double extent = nl_harness_param(r, "extent", 4.0, 1e-3, 1e4,
                                   "side of the noise-space square [0, extent)^2 the slice covers");
  double z = nl_harness_param(r, "z", NL_STUDY_SLICE_Z, -1e6, 1e6,
                              "z of the 2D slice through Perlin's improved 3D noise (64/3: "
                              "a third of a cell off the lattice planes at every octave)");
  nl_noise_window w = {0, 0, z, extent, size, size};
  return w;
}

nl_table *nl_study_octave_series(nl_harness *r, const nl_noise_window *win, int turbulence,
                                 const char *slides, const char *prefix, const char *title,
                                 nl_table **per_seed)
{
  nl_harness_text(r, "**Slides:** %s **Ours:** the slice z = %g of Perlin's improved 3D noise over "
                     "[0, %g)^2, %d seeds for the numbers.\n",
                  slides, win->z, win->size, nl_harness_seeds(r));
  const int oct[] = {1, 2, 3, 8};   /* the slides' panels (a)-(d) */
  nl_study_setting st[4];
  char labels[4][32];
  octave_settings(oct, 4, turbulence, st, labels);
  return nl_study_series(r, prefix, title, "improved", st, 4, win, per_seed);
}

/* sd of setting `name` at seed `seed` in a per-seed table; NAN if absent. */
static double seed_sd(const nl_table *t, const char *name, double seed)
{
  for (size_t k = 0; k < t->nrows; k++)
    if (nl_table_value(t, k, "seed") == seed && !strcmp(nl_table_text(t, k, "setting"), name))
      return nl_table_value(t, k, "sd");
  return NAN;
}

/* Mean and standard error of x[0..m-1]. */
static void mean_se(const double *x, size_t m, double *mean, double *se)
{
  *mean = gsl_stats_mean(x, 1, m);
  *se = m > 1 ? gsl_stats_sd_m(x, 1, m, *mean) / sqrt((double)m) : 0;
}

nl_table *nl_study_sd_law_table(const nl_table *dist, const nl_table *seeds,
                                const nl_table *ref_seeds, const char *ref)
{
  const char *cols[] = {"setting", "octaves", "gain",        "lacunarity",     "sd",
                        "sd_sd",   "sd1",     "sd_law",      "law",            "sd_over_law",
                        "sd_over_law_se",     "claim_ratio",    "sd_over_sep",    "sd_over_sep_se",
                        "sep_over_law",       "sep_over_law_se",  "seeds"};
  nl_table *t = nl_table_alloc(17, cols);
  for (size_t i = 0; i < dist->nrows; i++) {
    const char *name = nl_table_text(dist, i, "setting");
    int n = (int)nl_table_value(dist, i, "octaves");
    double g = nl_table_value(dist, i, "gain"), lac = nl_table_value(dist, i, "lacunarity");
    double sum = 0, sum2 = 0, a = 1;
    for (int j = 0; j < n; j++, a *= g) {
      sum += a;
      sum2 += a * a;
    }
    int same = lac == 1;
    double factor = same ? sum : sqrt(sum2);
    /* the per-seed ratios, paired by seed */
    double *ratio = nl_xmalloc(3 * seeds->nrows * sizeof *ratio), sd1 = 0;
    double *corr = ratio + seeds->nrows, *samp = corr + seeds->nrows;
    size_t m = 0;
    for (size_t k = 0; k < seeds->nrows; k++) {
      if (strcmp(nl_table_text(seeds, k, "setting"), name)) continue;
      double s1 = seed_sd(ref_seeds, ref, nl_table_value(seeds, k, "seed"));
      double sd = nl_table_value(seeds, k, "sd"), sep = nl_table_value(seeds, k, "sd_sep");
      ratio[m] = sd / (s1 * factor);
      corr[m] = sd / sep;
      samp[m++] = sep / (s1 * factor);
      sd1 += s1;
    }
    sd1 /= m;
    double r[6];
    mean_se(ratio, m, &r[0], &r[1]);
    mean_se(corr, m, &r[2], &r[3]);
    mean_se(samp, m, &r[4], &r[5]);
    free(ratio);
    nl_table_append(t, "siddddddsdddddddi", name, n, g, lac, nl_table_value(dist, i, "sd"),
                    nl_table_value(dist, i, "sd_sd"), sd1, sd1 * factor,
                    same ? "identical" : "independent", r[0], r[1], 1.0, r[2], r[3], r[4], r[5],
                    (int)m);
  }
  return t;
}

nl_table *nl_study_sd_law_control(nl_study_basis_kind kind, const nl_table *law,
                                  const nl_table *ref_seeds, const char *ref,
                                  const nl_noise_window *win, unsigned long seed0, int nseeds)
{
  const char *cols[] = {"setting", "octaves", "gain",        "lacunarity",     "sd",   "sd1",
                        "sd_law",  "sd_over_law", "sd_over_law_se", "claim_ratio", "seeds"};
  nl_table *t = nl_table_alloc(11, cols);
  size_t npix = (size_t)win->w * win->h;
  double *v = nl_xmalloc(npix * sizeof *v);
  double *ratio = nl_xmalloc((size_t)nseeds * sizeof *ratio);
  for (size_t i = 0; i < law->nrows; i++) {
    int n = (int)nl_table_value(law, i, "octaves");
    double g = nl_table_value(law, i, "gain"), sum2 = 0, a = 1, sd = 0, sd1 = 0;
    for (int j = 0; j < n; j++, a *= g) sum2 += a * a;
    /* the row's octaves and gains, every octave at the first one's frequency */
    nl_noise_octaves o = nl_noise_octaves_fbm(n, g, 1.0);
    for (int k = 0; k < nseeds; k++) {
      unsigned long seed = nl_seed_replicate(seed0, k);
      nl_basis *b;
      nl_error err;
      if (nl_basis_make(kind, NULL, seed, &b, &err)) { /* kind is a name in the code */
        fprintf(stderr, "noiselab: sd law control: %s\n", err.msg);
        abort();
      }
      nl_noise_fractal_grid(&b->noise, &o, win, v);
      nl_basis_free(b);
      double s = gsl_stats_sd(v, 1, npix), s1 = seed_sd(ref_seeds, ref, (double)seed);
      ratio[k] = s / (s1 * sqrt(sum2));
      sd += s / nseeds;
      sd1 += s1 / nseeds;
    }
    double mean, se;
    mean_se(ratio, (size_t)nseeds, &mean, &se);
    nl_table_append(t, "siddddddddi", nl_table_text(law, i, "setting"), n, g, 1.0, sd, sd1,
                    sd1 * sqrt(sum2), mean, se, 1.0, nseeds);
  }
  free(v);
  free(ratio);
  return t;
}

void nl_study_sd_law_text(nl_harness *r, const nl_table *law)
{
  long far = -1;
  double z = -1;
  for (size_t i = 0; i < law->nrows; i++) {
    double se = nl_table_value(law, i, "sd_over_law_se");
    if (strcmp(nl_table_text(law, i, "law"), "independent") || se == 0) continue;
    double zi = fabs(nl_table_value(law, i, "sd_over_law") - 1) / se;
    if (zi > z) {
      z = zi;
      far = (long)i;
    }
  }
  if (far < 0) return;
  size_t i = (size_t)far;
  nl_harness_text(r,
                  "Farthest from the law: %s, sd_over_law %.3f +- %.3f (%.1f standard errors). "
                  "Its factors: the octaves' correlation, sd_over_sep = %.3f +- %.3f (1 for "
                  "uncorrelated octaves), and each octave's own variance on the window against "
                  "the lone first octave's, sep_over_law = %.3f +- %.3f (1 when the pixels and the "
                  "window sample every octave alike).\n",
                  nl_table_text(law, i, "setting"), nl_table_value(law, i, "sd_over_law"),
                  nl_table_value(law, i, "sd_over_law_se"), z,
                  nl_table_value(law, i, "sd_over_sep"), nl_table_value(law, i, "sd_over_sep_se"),
                  nl_table_value(law, i, "sep_over_law"),
                  nl_table_value(law, i, "sep_over_law_se"));
}

void nl_study_montage(nl_harness *r, const nl_image *const *panels, const char *const *labels,
                      int n, int cols, const char *title, const char *file)
{
  nl_image *m = nl_image_montage(panels, labels, n, cols, title);
  nl_harness_write_image(r, m, file);
  nl_image_free(m);
}

nl_table *nl_study_radial_table(const double *const *img, const char *const *cols, int n, int size,
                                int first)
{
  int nbins = size / 2;
  const char **names = nl_xmalloc((size_t)(n + 1) * sizeof *names);
  names[0] = "freq";
  for (int i = 0; i < n; i++) names[i + 1] = cols[i];
  nl_table *t = nl_table_alloc((size_t)n + 1, names);
  double *f = nl_xmalloc((size_t)nbins * sizeof *f), *p = nl_xmalloc((size_t)n * nbins * sizeof *p);
  /* size is an experiment's checked side (nl_harness_param_fft_size); were
   * it refused all the same, the column is NaN, not minutes of transform. */
  for (int i = 0; i < n; i++)
    if (nl_spectrum_radial(img[i], size, size, nbins, f, p + (size_t)i * nbins, NULL))
      for (int b = 0; b < nbins; b++) f[b] = p[(size_t)i * nbins + b] = NAN;
  for (int b = first; b < nbins; b++) {
    size_t row = nl_table_append_empty(t);
    nl_table_set(t, row, "freq", f[b]);
    for (int i = 0; i < n; i++) nl_table_set(t, row, cols[i], p[(size_t)i * nbins + b]);
  }
  free(names); free(f); free(p);
  return t;
}

double nl_study_ks_channels(const nl_image *a, const nl_image *b, double *per)
{
  size_t n = (size_t)a->width * a->height, m = (size_t)b->width * b->height;
  double *x = nl_xmalloc(n * sizeof *x), *y = nl_xmalloc(m * sizeof *y), s = 0;
  for (int c = 0; c < 3; c++) {
    nl_stats_ks_result res;
    nl_byexample_channel(a, c, x);
    nl_byexample_channel(b, c, y);
    nl_stats_ks2_test(x, n, y, m, &res, NULL);
    if (per) per[c] = res.d;
    s += res.d / 3;
  }
  free(x);
  free(y);
  return s;
}

double nl_study_mean_where(const nl_table *t, const char *key, const char *value, const char *col,
                           const char *pcol, double alpha, int *below)
{
  size_t kc = nl_table_column_must(t, key);
  double s = 0;
  int n = 0, b = 0;
  char buf[32];
  for (size_t k = 0; k < t->nrows; k++)
    if (!strcmp(nl_table_cell_text(t, k, kc, buf), value)) {
      s += nl_table_value(t, k, col);
      if (pcol) b += nl_table_value(t, k, pcol) < alpha;
      n++;
    }
  if (below) *below = b;
  return n ? s / n : NAN;
}
