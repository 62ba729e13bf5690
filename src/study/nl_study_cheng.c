/* What the Cheng experiments share: the opening (--patterns, the standard
 * parameters), the runs over seeds on the run's threads, summary rows (mean
 * and spread over seeds), CDF tables, Welch tests between rows and the
 * controllability prose. */
#include "study/nl_study_cheng.h"
#include "base/nl_parallel.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void run_params(nl_harness *r, nl_cheng_config *c, int *grid)
{
  int q = nl_harness_quick(r);
  *c = nl_cheng_config_default();
  /* see nl_cheng.h on grid vs f */
  *grid = (int)nl_harness_param_int(
      r, "grid", 64, 2, 1024,
      "control grid G: the pattern is read as G x G control cells over the unit square");
  c->w1 = nl_harness_param(r, "w1", c->w1, 0, 1e6,
                           "weight w1 of the statistic term E_KS in E = w1 E_KS + w2 E_Con (Cheng "
                           "eq. 3.9; thesis 0.995)");
  c->w2 = nl_harness_param(r, "w2", c->w2, 0, 1e6,
                           "weight w2 of the control term E_Con in E = w1 E_KS + w2 E_Con (Cheng "
                           "eq. 3.9; thesis 0.005)");
  c->f1 = nl_harness_param(
      r, "f1", c->f1, 0, 1024,
      "starting frequency f1 of the fractal sum, f_l = f1 2^(l-1) (Cheng eq. 3.10; thesis 8)");
  c->a1 = nl_harness_param(
      r, "a1", c->a1, 1e-6, 1e6,
      "first octave's amplitude divisor a1, a_l = a1 2^(l-1) (Cheng eq. 3.10; thesis 4)");
  c->octaves = (int)nl_harness_param_int(
      r, "octaves", c->octaves, 1, NL_CHENG_MAX_OCTAVES,
      "octaves F of the fractal sum, one annealing level each (thesis 4)");
  c->origin = nl_harness_param(r, "origin", c->origin, 0, 1e6,
                               "origin o of the texture's domain [o, o + 1]^2 in the noise's "
                               "coordinates before eq. 3.10's f_l (1: no octave's lattice inside "
                               "another's; 0: the unit square at the noise's origin)");
  c->literal =
      (int)nl_harness_param_int(r, "literal", 0, 0, 1,
                                "1: the thesis's control formulas literally (V unscaled: c = V, "
                                "sin V, |V|); 0: V over its bound, c in [0, 1] (nl_cheng.h)");
  c->sched.n_temps =
      (int)nl_harness_param_int(r, "temps", q ? 8 : c->sched.n_temps, 1, 100000,
                                "annealing temperature steps per level (n_temps; quick 8)");
  c->sched.moves_per_var = nl_harness_param(
      r, "moves_per_var", q ? 5 : c->sched.moves_per_var, 1e-3, 1e6,
      "annealing moves per temperature, as a multiple of the level's variables (quick 5)");
}

static const char *const summary_cols[] = {
  "seeds", "E_ks", "E_ks_sd", "p_ks", "p_ks_min",
  "V_kuiper", "V_kuiper_sd", "p_kuiper", "p_kuiper_min",
  "chi2", "chi2_sd", "p_chi2",
  "E_con", "E_con_sd", "rms_con", "E",
  "uniform_ks", "uniform_kuiper",
  "roughness", "roughness_sd",
  "r_pattern", "r_pattern_sd", "contrast", "contrast_sd",
  "E_con_random", "E_con_random_sd", "E_con_const", "con_vs_const",
  "con_offset_frac", "con_contrast_frac", "con_shape_frac",
  "seam_ratio", "seam_ratio_sd",
};
#define NSUM (sizeof summary_cols / sizeof *summary_cols)

nl_table *nl_study_cheng_summary_alloc(int nlabels, const char *const *labels)
{
  const char *names[48];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < NSUM; i++) names[nlabels + (int)i] = summary_cols[i];
  return nl_table_alloc((size_t)nlabels + NSUM, names);
}

#define FIELD(evs, k, f, out)                                                                      \
  do {                                                                                             \
    for (int i_ = 0; i_ < (k); i_++) (out)[i_] = (evs)[i_].f;                                      \
  } while (0)

static double frac_at_least(const double *x, int k, double a)
{
  int n = 0;
  for (int i = 0; i < k; i++) n += x[i] >= a;
  return (double)n / k;
}

/* Appends one row: label cells as text (numbers read back as numbers), then
 * the mean (and sd, min) over the k runs; uniform_* = fraction of runs whose
 * p-value is >= 0.05 (not rejected as non-uniform at alpha = 0.05). */
static void summary_add(nl_table *t, int nlabels, const char *const *labels,
                        const nl_cheng_eval *evs, int k)
{
  double *x = nl_xmalloc((size_t)k * sizeof *x), row[NSUM];
  int c = 0;
  row[c++] = k;
  FIELD(evs, k, e_ks, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, p_ks, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_min(x, k);
  double uks = frac_at_least(x, k, 0.05);
  FIELD(evs, k, kuiper_v, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, p_kuiper, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_min(x, k);
  double uku = frac_at_least(x, k, 0.05);
  FIELD(evs, k, chi2, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, p_chi2, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, e_con, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, rms_con, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, e, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = uks;
  row[c++] = uku;
  FIELD(evs, k, roughness, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, r_pattern, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, contrast, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, e_con_random, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  row[c++] = evs[0].e_con_const;   /* the pattern's alone: the same for every seed */
  FIELD(evs, k, e_con, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING) / evs[0].e_con_const; /* > 1: worse than flat */
  /* E_Con's parts (nl_cheng_eval) as fractions of each run's E_Con, averaged */
  for (int i = 0; i < k; i++) x[i] = evs[i].e_con > 0 ? evs[i].e_con_offset / evs[i].e_con : 0;
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  for (int i = 0; i < k; i++) x[i] = evs[i].e_con > 0 ? evs[i].e_con_contrast / evs[i].e_con : 0;
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  for (int i = 0; i < k; i++) x[i] = evs[i].e_con > 0 ? evs[i].e_con_shape / evs[i].e_con : 0;
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  FIELD(evs, k, seam_ratio, x);
  row[c++] = nl_stats_mean(x, k, NL_STATS_RUNNING);
  row[c++] = nl_stats_sd(x, k, NL_STATS_RUNNING);
  size_t r = nl_table_append_empty(t);
  for (size_t i = 0; i < NSUM; i++) nl_table_set(t, r, summary_cols[i], row[i]);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
  free(x);
}

nl_table *nl_study_cheng_cdf_table(const nl_noise_grad2 *const *tables, const char *const *names,
                                   int n)
{
  const char *cols[16];
  char buf[16][48];
  cols[0] = "F";
  for (int i = 0; i < n; i++) {
    snprintf(buf[i], sizeof buf[i], "u_%s", names[i]);
    cols[i + 1] = buf[i];
  }
  nl_table *t = nl_table_alloc((size_t)n + 1, cols);
  size_t m = tables[0]->m;
  double *sorted = nl_xmalloc((size_t)n * m * sizeof *sorted), row[16];
  for (int i = 0; i < n; i++) {
    memcpy(sorted + (size_t)i * m, tables[i]->angle, m * sizeof *sorted);
    nl_stats_sort(sorted + (size_t)i * m, m);
  }
  for (size_t q = 0; q < m; q++) {
    row[0] = (double)(q + 1) / (double)m;   /* ECDF just after the q-th order statistic */
    for (int i = 0; i < n; i++) row[i + 1] = sorted[(size_t)i * m + q] / NL_TWO_PI;
    nl_table_append_doubles(t, row);
  }
  free(sorted);
  return t;
}

void nl_study_cheng_open(nl_study_cheng *s, const char *name, const char *title, int *argc,
                         char **argv)
{
  nl_error err;
  if (nl_study_cheng_patterns_parse(argc, argv, &s->patterns, &err)) {
    fprintf(stderr, "%s: %s\n", name, err.msg);
    exit(2);
  }
  s->r = nl_harness_begin(name, title, *argc, argv);
  run_params(s->r, &s->c, &s->grid);
  s->role = NULL;
  s->cost = NULL;
}

void nl_study_cheng_ready(nl_study_cheng *s)
{
  nl_harness *r = s->r;
  nl_harness_params_done(r);
  nl_error err;
  if (nl_cheng_config_check(&s->c, &err)) nl_harness_die(r, 2, "%s", err.msg);
  /* Every pattern loads before the output folder is touched (nl_harness_begin
   * does not touch it; the first write does), and after --help / --params,
   * which need no image (nl_study_cheng.h). */
  if (nl_study_cheng_patterns_check(s->patterns, s->grid, &err))
    nl_harness_die(r, 2,
                   "control patterns: %s (make them with build/tools/noiselab-patterns "
                   "data/patterns, or pass --patterns DIR)",
                   err.msg);
  nl_harness_note(r, "patterns", "%s", s->patterns);
}

nl_cheng_pattern *nl_study_cheng_pattern(const nl_study_cheng *s, const char *name)
{
  return nl_study_cheng_pattern_load_or_die(nl_harness_name(s->r), s->patterns, name, s->grid);
}

/* Item i of nl_study_cheng_runs: case i / k, seed i % k: nl_cheng_run at
 * seed nl_seed_replicate(seed0, seed). It writes only its own slots (evs[i],
 * st[i], err[i], and firsts[case] for seed 0) and draws only from
 * nl_seed_replicate(seed0, seed), so the results do not depend on the thread
 * count (nl_parallel.h). */
typedef struct {
  const nl_cheng_config *cs;
  const nl_cheng_pattern *const *pats;
  unsigned long seed0;
  int k;
  nl_cheng_eval *evs;
  nl_noise_grad2 **firsts;
  nl_noise_grad2 **all;   /* NULL, or every run's table at its item's slot */
  nl_status *st;
  nl_error *err;
} runs_job;

static void run_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  runs_job *j = ctx;
  size_t q = i / (size_t)j->k, seed = i % (size_t)j->k;
  nl_noise_grad2 *g = NULL;
  j->st[i] = nl_cheng_run(&j->cs[q], j->pats[q], nl_seed_replicate(j->seed0, (long)seed),
                          &j->evs[i], NULL, &g, &j->err[i]);
  if (j->all) j->all[i] = g;
  else if (seed == 0 && j->firsts) j->firsts[q] = g;
  else nl_noise_grad2_free(g);
}

static nl_cheng_eval *runs(const nl_study_cheng *s, int n, const nl_cheng_config *cs,
                           const nl_cheng_pattern *const *pats, nl_noise_grad2 **firsts,
                           nl_noise_grad2 **all)
{
  int k = nl_harness_seeds(s->r);
  size_t items = (size_t)n * (size_t)k;
  nl_cheng_eval *evs = nl_xmalloc(items * sizeof *evs);
  nl_status *st = nl_xmalloc(items * sizeof *st);
  nl_error *err = nl_xmalloc(items * sizeof *err);
  unsigned long seed0 =
      s->role ? nl_seed_stream(nl_harness_seed(s->r), s->role, 0) : nl_harness_seed(s->r);
  runs_job j = { cs, pats, seed0, k, evs, firsts, all, st, err };
  nl_parallel_for(items, nl_harness_threads(s->r), run_item, &j);
  /* the first failure in case and seed order, as a serial loop met it */
  for (size_t i = 0; i < items; i++)
    if (st[i]) nl_harness_die(s->r, 1, "%s", err[i].msg);
  free(st);
  free(err);
  return evs;
}

nl_cheng_eval *nl_study_cheng_runs(const nl_study_cheng *s, int n, const nl_cheng_config *cs,
                                   const nl_cheng_pattern *const *pats, nl_noise_grad2 **firsts)
{
  return runs(s, n, cs, pats, firsts, NULL);
}

nl_cheng_eval *nl_study_cheng_runs_tables(const nl_study_cheng *s, int n,
                                          const nl_cheng_config *cs,
                                          const nl_cheng_pattern *const *pats,
                                          nl_noise_grad2 **tables)
{
  return runs(s, n, cs, pats, NULL, tables);
}

void nl_study_cheng_rows_add(const nl_study_cheng *s, nl_table *sum, int nlabels,
                             const char *const *labels, const nl_cheng_eval *evs)
{
  int k = nl_harness_seeds(s->r);
  summary_add(sum, nlabels, labels, evs, k);
  if (s->cost) {
    char name[160] = "";
    for (int i = 0; i < nlabels; i++) {
      if (i) strncat(name, "/", sizeof name - strlen(name) - 1);
      strncat(name, labels[i], sizeof name - strlen(name) - 1);
    }
    double moves = 0, cpu = 0, *t = nl_xmalloc((size_t)k * sizeof *t);
    for (int i = 0; i < k; i++) {
      moves += (double)evs[i].moves;
      cpu += evs[i].cpu_seconds;
      t[i] = evs[i].cpu_seconds;
    }
    nl_table_append(s->cost, "sddddd", name, (double)k, moves / k, cpu / k,
                    k > 1 ? gsl_stats_sd(t, 1, (size_t)k) : 0.0, cpu > 0 ? moves / cpu : NAN);
    free(t);
  }
}

nl_noise_grad2 *nl_study_cheng_seeds(const nl_study_cheng *s, const nl_cheng_config *c,
                                     const nl_cheng_pattern *pat, nl_table *sum, int nlabels,
                                     const char *const *labels)
{
  nl_noise_grad2 *first = NULL;
  nl_cheng_eval *evs = nl_study_cheng_runs(s, 1, c, &pat, &first);
  nl_study_cheng_rows_add(s, sum, nlabels, labels, evs);
  free(evs);
  return first;
}

void nl_study_cheng_montage(nl_harness *r, nl_image **panels, const char *const *labels, int n,
                            int cols, const char *title, const char *file)
{
  nl_image *m = nl_image_montage((const nl_image *const *)panels, labels, n, cols, title);
  nl_harness_write_image(r, m, file);
  nl_image_free(m);
  for (int i = 0; i < n; i++) nl_image_free(panels[i]);
}

double nl_study_column_min(const nl_table *t, const char *col)
{
  double m = INFINITY;
  for (size_t q = 0; q < t->nrows; q++) m = fmin(m, nl_table_value(t, q, col));
  return m;
}

int nl_study_cheng_control_text(nl_harness *r, const nl_table *sum, int nlabels)
{
  double rlo = INFINITY, rhi = -INFINITY, clo = INFINITY, chi = -INFINITY;
  int worse = 0, better_random = 0;
  for (size_t q = 0; q < sum->nrows; q++) {
    double rp = nl_table_value(sum, q, "r_pattern"), ct = nl_table_value(sum, q, "contrast");
    rlo = fmin(rlo, rp);
    rhi = fmax(rhi, rp);
    clo = fmin(clo, ct);
    chi = fmax(chi, ct);
    better_random += nl_table_value(sum, q, "E_con") < nl_table_value(sum, q, "E_con_random");
  }
  nl_harness_text(r,
                  "Controllability: Pearson r between the control value and the pattern "
                  "%.2f..%.2f, contrast (sd of the control value) %.3f..%.3f; the optimised E_Con "
                  "is below the unoptimised start table's in %d of %zu rows.\n",
                  rlo, rhi, clo, chi, better_random, sum->nrows);
  size_t cap = 256 + 160 * sum->nrows, len = 0;
  char *list = nl_xmalloc(cap);
  list[0] = 0;
  for (size_t q = 0; q < sum->nrows; q++) {
    double e = nl_table_value(sum, q, "E_con"), e0 = nl_table_value(sum, q, "E_con_const");
    if (!(e > e0)) continue;
    char lab[160] = "";
    for (int i = 0; i < nlabels; i++) {
      char buf[32];
      snprintf(lab + strlen(lab), sizeof lab - strlen(lab), "%s%s", i ? "/" : "",
               nl_table_cell_text(sum, q, (size_t)i, buf));
    }
    len += (size_t)snprintf(list + len, cap - len, "%s%s (E_Con %.4g +- %.3g vs %.4g, r %.2f)",
                            worse ? "; " : "", lab, e, nl_table_value(sum, q, "E_con_sd"), e0,
                            nl_table_value(sum, q, "r_pattern"));
    worse++;
  }
  if (worse)
    nl_harness_text(
        r,
        "**Not controlled in the E_Con sense** (%d of %zu rows): the optimised E_Con is worse than "
        "that of the best constant image (a flat image at the pattern's mean): %s.\n",
        worse, sum->nrows, list);
  else
    nl_harness_text(
        r, "Every row's optimised E_Con is below the best constant image's (con_vs_const < 1).\n");
  free(list);
  return worse;
}

nl_table *nl_study_cheng_welch_alloc(void)
{
  const char *cc[] = { "group",  "quantity", "a",     "b",        "mean_a", "sd_a",
                       "mean_b", "sd_b",     "seeds", "diff_pct", "p_welch" };
  return nl_table_alloc(sizeof cc / sizeof *cc, cc);
}

double nl_study_cheng_welch_add(nl_table *t, const nl_table *sum, size_t ra, size_t rb,
                                const char *col, const char *group, const char *a, const char *b)
{
  char sdcol[64];
  snprintf(sdcol, sizeof sdcol, "%s_sd", col);
  double ma = nl_table_value(sum, ra, col), sa = nl_table_value(sum, ra, sdcol);
  double mb = nl_table_value(sum, rb, col), sb = nl_table_value(sum, rb, sdcol), p;
  size_t na = (size_t)nl_table_value(sum, ra, "seeds");
  size_t nb = (size_t)nl_table_value(sum, rb, "seeds");
  nl_error err;
  if (nl_stats_welch_p(ma, sa, na, mb, sb, nb, &p, &err))
    p = ma == mb ? 1 : 0;   /* nothing to test */
  nl_table_append(t, "ssssddddddd", group, col, a, b, ma, sa, mb, sb, (double)na,
                  100 * (ma - mb) / mb, p);
  return p;
}

nl_table *nl_study_cheng_tables_alloc(int nlabels, const char *const *labels)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  names[nlabels] = "k";
  names[nlabels + 1] = "angle";
  names[nlabels + 2] = "perm";
  return nl_table_alloc((size_t)nlabels + 3, names);
}

void nl_study_cheng_tables_add(nl_table *t, int nlabels, const char *const *labels,
                               const nl_noise_grad2 *g)
{
  for (size_t k = 0; k < g->m; k++) {
    size_t r = nl_table_append_empty(t);
    for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
    nl_table_set(t, r, "k", (double)k);
    nl_table_set(t, r, "angle", g->angle[k]);
    nl_table_set(t, r, "perm", (double)g->perm[k]);
  }
}
