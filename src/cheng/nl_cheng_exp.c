/* The loops and tables experiments C1-C4 and C7 share: standard parameters,
 * runs over seeds, summary rows (mean and spread), CDF and histogram tables. */
#include "cheng/nl_cheng_internal.h"
#include "report/nl_report.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void run_params(nl_run *r, nl_cheng_config *c, int *grid)
{
  int q = nl_run_quick(r);
  *c = nl_cheng_config_default();
  *grid = (int)nl_run_param_int(r, "grid", 64, 2, 1024,
                                "control grid G: the pattern is read as G x G control cells over the unit square");   /* see nl_cheng.h on grid vs f */
  c->w1 = nl_run_param(r, "w1", c->w1, 0, 1e6,
                       "weight w1 of the statistic term E_KS in E = w1 E_KS + w2 E_Con (Cheng eq. 3.9; thesis 0.995)");
  c->w2 = nl_run_param(r, "w2", c->w2, 0, 1e6,
                       "weight w2 of the control term E_Con in E = w1 E_KS + w2 E_Con (Cheng eq. 3.9; thesis 0.005)");
  c->f1 = nl_run_param(r, "f1", c->f1, 0, 1024,
                       "starting frequency f1 of the fractal sum, f_l = f1 2^(l-1) (Cheng eq. 3.10; thesis 8)");
  c->a1 = nl_run_param(r, "a1", c->a1, 1e-6, 1e6,
                       "first octave's amplitude divisor a1, a_l = a1 2^(l-1) (Cheng eq. 3.10; thesis 4)");
  c->octaves = (int)nl_run_param_int(r, "octaves", c->octaves, 1, NL_CHENG_MAX_OCTAVES,
                                     "octaves F of the fractal sum, one annealing level each (thesis 4)");
  c->sched.n_temps = (int)nl_run_param_int(r, "temps", q ? 8 : c->sched.n_temps, 1, 100000,
                                           "annealing temperature steps per level (n_temps; quick 8)");
  c->sched.moves_per_var = nl_run_param(r, "moves_per_var", q ? 5 : c->sched.moves_per_var, 1e-3, 1e6,
                                        "annealing moves per temperature, as a multiple of the level's variables (quick 5)");
}

nl_run *nl_cheng_begin(const char *name, const char *title, int *argc, char **argv,
                       nl_cheng_config *c, int *grid, const char **patterns)
{
  nl_error err;
  if (nl_cheng_patterns_parse(argc, argv, patterns, &err)) {
    fprintf(stderr, "%s: %s\n", name, err.msg);
    exit(2);
  }
  nl_run *r = nl_run_begin(name, title, *argc, argv);
  run_params(r, c, grid);
  /* Every pattern loads before the output folder is touched (nl_run_begin
   * does not touch it; the first write does). */
  if (nl_cheng_patterns_check(*patterns, *grid, &err))
    nl_run_die(r, 2, "control patterns: %s (make them with build/tools/noiselab-patterns "
                     "data/patterns, or pass --patterns DIR)", err.msg);
  return r;
}

void nl_cheng_params_done(nl_run *r, const nl_cheng_config *c, const char *patterns)
{
  nl_run_params_done(r);
  nl_error err;
  if (nl_cheng_config_check(c, &err)) nl_run_die(r, 2, "%s", err.msg);
  nl_run_note(r, "patterns", "%s", patterns);
}

nl_status nl_cheng_run_seeds(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                             unsigned long seed0, int k, nl_cheng_eval *evs, nl_grad2 **first,
                             nl_error *err)
{
  for (int s = 0; s < k; s++) {
    nl_status st = nl_cheng_run(c, pat, nl_seed_replicate(seed0, s), &evs[s], NULL,
                                s == 0 ? first : NULL, err);
    if (st) return st;
  }
  return NL_OK;
}

static const char *const summary_cols[] = {
  "seeds", "E_ks", "E_ks_sd", "p_ks", "p_ks_min", "V_kuiper", "V_kuiper_sd", "p_kuiper",
  "p_kuiper_min", "chi2", "chi2_sd", "p_chi2", "E_con", "E_con_sd", "rms_con", "E",
  "uniform_ks", "uniform_kuiper", "roughness", "roughness_sd"};
#define NSUM (sizeof summary_cols / sizeof *summary_cols)

nl_table *nl_cheng_summary_alloc(int nlabels, const char *const *labels)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < NSUM; i++) names[nlabels + (int)i] = summary_cols[i];
  return nl_table_alloc((size_t)nlabels + NSUM, names);
}

#define FIELD(evs, k, f, out) do { for (int i_ = 0; i_ < (k); i_++) (out)[i_] = (evs)[i_].f; } while (0)

static double sd_of(const double *x, int k) { return k > 1 ? gsl_stats_sd(x, 1, (size_t)k) : 0.0; }
static double min_of(const double *x, int k) { double m = x[0]; for (int i = 1; i < k; i++) m = fmin(m, x[i]); return m; }
static double frac_at_least(const double *x, int k, double a)
{
  int n = 0;
  for (int i = 0; i < k; i++) n += x[i] >= a;
  return (double)n / k;
}

/* Appends one row: label cells as text (numbers read back as numbers), then
 * the mean (and sd, min) over the k runs; uniform_* = fraction of runs whose
 * p-value is >= 0.05 (not rejected as non-uniform at alpha = 0.05). */
void nl_cheng_summary_add(nl_table *t, int nlabels, const char *const *labels,
                          const nl_cheng_eval *evs, int k)
{
  double *x = nl_xmalloc((size_t)k * sizeof *x), row[32];
  int c = nlabels;
  row[c++] = k;
  FIELD(evs, k, e_ks, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = sd_of(x, k);
  FIELD(evs, k, p_ks, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = min_of(x, k);
  double uks = frac_at_least(x, k, 0.05);
  FIELD(evs, k, kuiper_v, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = sd_of(x, k);
  FIELD(evs, k, p_kuiper, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = min_of(x, k);
  double uku = frac_at_least(x, k, 0.05);
  FIELD(evs, k, chi2, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = sd_of(x, k);
  FIELD(evs, k, p_chi2, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k);
  FIELD(evs, k, e_con, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = sd_of(x, k);
  FIELD(evs, k, rms_con, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k);
  FIELD(evs, k, e, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k);
  row[c++] = uks;
  row[c++] = uku;
  FIELD(evs, k, roughness, x); row[c++] = gsl_stats_mean(x, 1, (size_t)k); row[c++] = sd_of(x, k);
  for (int i = 0; i < nlabels; i++) row[i] = 0;
  nl_table_append_doubles(t, row);
  size_t r = t->nrows - 1;
  for (int i = 0; i < nlabels; i++) {
    t->num[r * t->ncols + (size_t)i] = NAN;
    t->text[r * t->ncols + (size_t)i] = nl_xstrdup(labels[i]);
  }
  free(x);
}

nl_table *nl_cheng_cdf_table(const nl_grad2 *const *tables, const char *const *names, int n)
{
  const char *cols[16];
  char buf[16][48];
  cols[0] = "F";
  for (int i = 0; i < n; i++) { snprintf(buf[i], sizeof buf[i], "u_%s", names[i]); cols[i + 1] = buf[i]; }
  nl_table *t = nl_table_alloc((size_t)n + 1, cols);
  size_t m = tables[0]->m;
  double *sorted = nl_xmalloc((size_t)n * m * sizeof *sorted), row[16];
  for (int i = 0; i < n; i++) {
    memcpy(sorted + (size_t)i * m, tables[i]->angle, m * sizeof *sorted);
    nl_sort_double(sorted + (size_t)i * m, m);
  }
  for (size_t q = 0; q < m; q++) {
    row[0] = (double)(q + 1) / (double)m;   /* ECDF just after the q-th order statistic */
    for (int i = 0; i < n; i++) row[i + 1] = sorted[(size_t)i * m + q] / NL_TWO_PI;
    nl_table_append_doubles(t, row);
  }
  free(sorted);
  return t;
}

nl_table *nl_cheng_hist_table(const nl_grad2 *const *tables, const char *const *names, int n,
                              size_t bins)
{
  const char *cols[16];
  cols[0] = "theta";
  for (int i = 0; i < n; i++) cols[i + 1] = names[i];
  nl_table *t = nl_table_alloc((size_t)n + 1, cols);
  gsl_histogram *h[16];
  for (int i = 0; i < n; i++) h[i] = nl_histogram_uniform(tables[i]->angle, tables[i]->m, bins, 0, NL_TWO_PI, NULL, NULL);
  double row[16];
  for (size_t b = 0; b < bins; b++) {
    row[0] = (b + 0.5) * NL_TWO_PI / (double)bins;
    for (int i = 0; i < n; i++) row[i + 1] = h[i]->bin[b];
    nl_table_append_doubles(t, row);
  }
  for (int i = 0; i < n; i++) gsl_histogram_free(h[i]);
  return t;
}

nl_image *nl_cheng_value_image(const nl_grad2 *g, const nl_cheng_config *c, int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_cheng_value_grid(g, c, size, size, v);
  nl_image *im = nl_cheng_grey_image(v, size, size);
  free(v);
  return im;
}

nl_image *nl_cheng_texture_image(const nl_grad2 *g, const nl_cheng_config *c, int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_cheng_value_grid(g, c, size, size, v);
  nl_image *im = nl_cheng_texture(c->con, v, size, size);
  free(v);
  return im;
}

nl_image *nl_cheng_pattern_panel(const nl_cheng_pattern *p, int size)
{
  nl_image *small = nl_cheng_pattern_image(p), *im = nl_image_alloc(size, size, 3);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++)
      memcpy(nl_image_pixel(im, x, y), nl_image_pixel(small, x * p->grid / size, y * p->grid / size),
             3 * sizeof(float));
  nl_image_free(small);
  return im;
}

nl_table *nl_cheng_matrix_table(const double *v, int w, int h)
{
  char (*names)[16] = nl_xmalloc((size_t)w * sizeof *names);
  const char **cols = nl_xmalloc((size_t)w * sizeof *cols);
  for (int x = 0; x < w; x++) { snprintf(names[x], sizeof names[x], "c%d", x); cols[x] = names[x]; }
  nl_table *t = nl_table_alloc((size_t)w, cols);
  for (int y = 0; y < h; y++) nl_table_append_doubles(t, v + (size_t)y * w);
  free(cols);
  free(names);
  return t;
}

double nl_cheng_ks_median(size_t n)
{
  double lo = 0, hi = 1;   /* bisection on the exact CDF of D_n */
  for (int it = 0; it < 60; it++) {
    double mid = 0.5 * (lo + hi);
    if (nl_ks_cdf(n, mid, NULL) < 0.5) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}
