/* C8's harness side: seeds into a summary, ECDF and voxel tables, slices
 * (sphere.h). */
#include "sphere.h"
#include "indep.h"
#include "base/nl_parallel.h"
#include "study/nl_study.h"
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* clang-format off */
static const char *const sum_cols[] = {
  "pattern", "table", "seeds", "E_stat", "E_stat_sd", "D_z", "p_z", "p_z_min", "D_phi", "p_phi",
  "p_phi_min", "p_stat", "p_stat_min", "uniform", "V_kuiper", "p_kuiper", "p_kuiper_min",
  "R_rayleigh", "p_rayleigh", "p_rayleigh_min", "E_con", "E_con_sd", "rms_con", "E", "r_pattern",
  "r_pattern_sd", "contrast", "contrast_sd", "E_con_random", "E_con_random_sd", "E_con_const",
  "con_vs_const", "con_offset_frac", "con_contrast_frac", "con_shape_frac", "E_con_offset",
  "mean_D", "chi2_indep", "p_indep", "p_indep_min", "p_indep_bonf", "p_indep_pooled", "p_joint",
  "p_joint_min"
};
/* clang-format on */
#define NSUM (sizeof sum_cols / sizeof *sum_cols)

nl_table *c8_summary_alloc(void) { return nl_table_alloc(NSUM, sum_cols); }

#define FIELD(f)                                                                                   \
  for (int i = 0; i < k; i++) x[i] = ev[i].f
/* mean, then sd (kind 0) or min (kind 1) of field f into the next columns */
#define PUT(f, kind)                                                                               \
  do {                                                                                             \
    FIELD(f);                                                                                      \
    nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING));                    \
    nl_table_set(t, row, sum_cols[c++],                                                            \
                 (kind) ? nl_stats_min(x, k) : nl_stats_sd(x, k, NL_STATS_RUNNING));               \
  } while (0)
#define PUT1(f)                                                                                    \
  do {                                                                                             \
    FIELD(f);                                                                                      \
    nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING));                    \
  } while (0)

/* mean over seeds of E_Con's part f as a fraction of each run's E_Con */
#define FRAC(f)                                                                                    \
  do {                                                                                             \
    for (int i = 0; i < k; i++) x[i] = ev[i].e_con > 0 ? ev[i].f / ev[i].e_con : 0;                \
    nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING));                    \
  } while (0)
/* mean and min over seeds of the independence test's field f, from ind */
#define IND(f, min)                                                                                \
  do {                                                                                             \
    for (int i = 0; i < k; i++) x[i] = ind[i].f;                                                   \
    nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING));                    \
    if (min) nl_table_set(t, row, sum_cols[c++], nl_stats_min(x, k));                              \
  } while (0)

static void summary_add(nl_table *t, const char *pattern, const char *table,
                        const nl_cheng3_eval *ev, const c8_indep *ind, const nl_cheng3_pattern *pat,
                        int k)
{
  double *x = nl_xmalloc((size_t)k * sizeof *x);
  size_t row = nl_table_append_empty(t);
  int c = 0, pass = 0;
  nl_table_set_text(t, row, sum_cols[c++], pattern);
  nl_table_set_text(t, row, sum_cols[c++], table);
  nl_table_set(t, row, sum_cols[c++], k);
  PUT(e_stat, 0);
  PUT1(d_z);
  PUT(p_z, 1);
  PUT1(d_phi);
  PUT(p_phi, 1);
  PUT(p_stat, 1);
  for (int i = 0; i < k; i++) pass += ev[i].p_stat >= 0.05;
  nl_table_set(t, row, sum_cols[c++], pass / (double)k);
  PUT1(kuiper_v);
  PUT(p_kuiper, 1);
  PUT1(rayleigh_r);
  PUT(p_rayleigh, 1);
  PUT(e_con, 0);
  PUT1(rms_con);
  PUT1(e);
  PUT(r_pattern, 0);
  PUT(contrast, 0);
  PUT(e_con_random, 0);
  nl_table_set(t, row, sum_cols[c++], ev[0].e_con_const); /* the pattern's alone */
  FIELD(e_con);
  nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING) / ev[0].e_con_const);
  FRAC(e_con_offset);
  FRAC(e_con_contrast);
  FRAC(e_con_shape);
  PUT1(e_con_offset);
  double md = 0;
  for (size_t q = 0; q < pat->n; q++) md += pat->d[q];
  nl_table_set(t, row, sum_cols[c++], md / (double)pat->n);
  for (int i = 0; i < k; i++) x[i] = ind[i].chi2_indep;
  nl_table_set(t, row, sum_cols[c++], nl_stats_mean(x, k, NL_STATS_RUNNING));
  IND(p_indep, 1);
  /* all k tables independent: Bonferroni over the seeds */
  nl_table_set(t, row, sum_cols[c++], fmin(1.0, k * nl_stats_min(x, k)));
  /* pooled: the seeds' statistics summed against chi2 with the summed df */
  double chi = 0, df = 0;
  for (int i = 0; i < k; i++) {
    chi += ind[i].chi2_indep;
    df += ind[i].df_indep;
  }
  nl_table_set(t, row, sum_cols[c++], gsl_cdf_chisq_Q(chi, df));
  IND(p_joint, 1);
  free(x);
}

/* Seed i of c8_seeds: its own slots (ev[i], ev0[i], st[i],
 * err[i], and the table for seed 0), its own seed nl_seed_replicate(seed, i),
 * so the results do not depend on the thread count (nl_parallel.h). */
typedef struct {
  const nl_cheng3_config *c;
  const nl_cheng3_pattern *pat;
  unsigned long seed;
  nl_cheng3_eval *ev, *ev0;
  c8_indep *ind, *ind0; /* z-phi independence of the optimised and start tables */
  c8_indep *pair;       /* of the optimised table's z and phi paired by rank */
  nl_cheng3_table *first;
  nl_status *st;
  nl_error *err;
} seeds_job;

static void seed_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  seeds_job *j = ctx;
  unsigned long seed = nl_seed_replicate(j->seed, (long)i);
  nl_cheng3_table *t = NULL;
  j->st[i] = nl_cheng3_run(j->c, j->pat, seed, &j->ev[i], &j->ev0[i], NULL, &t, &j->err[i]);
  if (j->st[i] != NL_OK) return;
  c8_indep_test(t, C8_INDEP_BINS, &j->ind[i]);
  c8_indep_paired(t->z, t->phi, t->m, C8_INDEP_BINS, &j->pair[i]);
  nl_cheng3_table *t0 = nl_cheng3_table_alloc(j->c->m); /* the run's start table */
  nl_cheng3_table_seed(t0, seed);
  c8_indep_test(t0, C8_INDEP_BINS, &j->ind0[i]);
  nl_cheng3_table_free(t0);
  if (i == 0)
    j->first = t;
  else
    nl_cheng3_table_free(t);
}

/* clang-format off */
static const char *const base_cols[] = {
  "pattern", "table", "seeds", "E_con", "E_con_sd", "chi2_indep", "p_indep_bonf"
};
/* clang-format on */

nl_table *c8_baselines_alloc(void)
{
  return nl_table_alloc(sizeof base_cols / sizeof *base_cols, base_cols);
}

/* mean and sd over the k seeds of x */
static void mean_sd(const double *x, int k, double *m, double *sd)
{
  *m = nl_stats_mean(x, (size_t)k, NL_STATS_RUNNING);
  *sd = nl_stats_sd(x, (size_t)k, NL_STATS_RUNNING);
}

static void baselines_add(nl_table *b, const char *name, const nl_cheng3_eval *ev,
                          const nl_cheng3_eval *ev0, const c8_indep *pair, int k)
{
  double *x = nl_xmalloc((size_t)k * sizeof *x), m, sd;
  for (int i = 0; i < k; i++) x[i] = ev[i].e_con;
  mean_sd(x, k, &m, &sd);
  nl_table_append(b, "ssdddss", name, "optimised", (double)k, m, sd, "n/a", "n/a");
  nl_table_append(b, "ssdddss", name, "flat", (double)k, ev[0].e_con_const, 0.0, "n/a", "n/a");
  for (int i = 0; i < k; i++) x[i] = ev0[i].e_con;
  mean_sd(x, k, &m, &sd);
  nl_table_append(b, "ssdddss", name, "random", (double)k, m, sd, "n/a", "n/a");
  double chi = 0, pmin = 1;
  for (int i = 0; i < k; i++) {
    chi += pair[i].chi2_indep / k;
    pmin = fmin(pmin, pair[i].p_indep);
  }
  nl_table_append(b, "ssdssdd", name, "paired", (double)k, "n/a", "n/a", chi, fmin(1.0, k * pmin));
  free(x);
}

nl_cheng3_table *c8_seeds(nl_harness *r, const nl_cheng3_config *c, const nl_cheng3_pattern *pat,
                          nl_table *sum, nl_table *base, const char *name,
                          nl_cheng3_table **start, double *seconds)
{
  int k = nl_harness_seeds(r);
  nl_cheng3_eval *ev = nl_xmalloc(2 * (size_t)k * sizeof *ev), *ev0 = ev + k;
  nl_status *st = nl_xcalloc((size_t)k, sizeof *st);
  nl_error *err = nl_xmalloc((size_t)k * sizeof *err);
  double t0 = nl_time_now();
  /* The k seed runs on the run's threads; rows from them in seed order. */
  c8_indep *ind = nl_xmalloc(3 * (size_t)k * sizeof *ind);
  seeds_job j = { c, pat, nl_harness_seed(r), ev, ev0, ind, ind + k, ind + 2 * k, NULL, st, err };
  nl_parallel_for((size_t)k, nl_harness_threads(r), seed_item, &j);
  for (int i = 0; i < k; i++) /* the first failure in seed order, as a serial loop met it */
    if (st[i] != NL_OK) nl_harness_die(r, 1, "%s", err[i].msg);
  nl_harness_progress(r, 1.0, name);
  if (seconds) *seconds = nl_time_now() - t0;
  summary_add(sum, name, "optimised", ev, ind, pat, k);
  summary_add(sum, name, "random", ev0, ind + k, pat, k);
  baselines_add(base, name, ev, ev0, ind + 2 * k, k);
  *start = nl_cheng3_table_alloc(c->m);
  nl_cheng3_table_seed(*start,
                       nl_seed_replicate(nl_harness_seed(r), 0)); /* the first run's start */
  free(ev);
  free(ind);
  free(st);
  free(err);
  return j.first;
}

static void sorted_u(const double *x, size_t m, double a, double b, double *out)
{
  for (size_t i = 0; i < m; i++) out[i] = (x[i] - a) / (b - a);
  nl_stats_sort(out, m);
}

nl_table *c8_ecdf_table(const nl_cheng3_table *opt, const nl_cheng3_table *rnd)
{
  const char *cols[] = { "F", "z_opt", "phi_opt", "z_rand", "phi_rand" };
  nl_table *t = nl_table_alloc(5, cols);
  size_t m = opt->m;
  double *u = nl_xmalloc(4 * m * sizeof *u);
  sorted_u(opt->z, m, -1, 1, u);
  sorted_u(opt->phi, m, 0, NL_TWO_PI, u + m);
  sorted_u(rnd->z, m, -1, 1, u + 2 * m);
  sorted_u(rnd->phi, m, 0, NL_TWO_PI, u + 3 * m);
  for (size_t i = 0; i < m; i++)
    nl_table_append(t, "ddddd", (i + 1.0) / (double)m, u[i], u[m + i], u[2 * m + i], u[3 * m + i]);
  free(u);
  return t;
}

static double pattern_at(const nl_cheng3_pattern *p, double x, double y, double z)
{
  int g = p->grid, i = (int)(x * g), j = (int)(y * g), k = (int)(z * g);
  i = i < g ? i : g - 1;
  j = j < g ? j : g - 1;
  k = k < g ? k : g - 1;
  return p->d[((size_t)k * g + j) * g + i];
}

nl_table *c8_voxel_table(const nl_cheng3_table *t, const nl_cheng3_config *c,
                         const nl_cheng3_pattern *pat, int n)
{
  size_t nn = (size_t)n * n * n, inside = 0;
  double *v = nl_xmalloc(2 * nn * sizeof *v), *s = v + nn;
  nl_cheng3_value_grid(t, c, n, v);
  memcpy(s, v, nn * sizeof *s);
  nl_stats_sort(s, nn);
  for (size_t q = 0; q < pat->n; q++) inside += pat->d[q] >= 0.5;
  size_t ntop = (size_t)llround((double)inside / (double)pat->n * (double)nn);
  double level = ntop ? s[nn - ntop] : INFINITY; /* c >= level: the top ntop voxels */
  const char *cols[] = { "x", "y", "z", "D", "c", "in_pattern", "top_c" };
  nl_table *tab = nl_table_alloc(7, cols);
  for (int k = 0; k < n; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++) {
        double x = (i + 0.5) / n, y = (j + 0.5) / n, z = (k + 0.5) / n,
               d = pattern_at(pat, x, y, z);
        double cv = v[((size_t)k * n + j) * n + i];
        nl_table_append(tab, "dddddii", x, y, z, d, cv, d >= 0.5, cv >= level);
      }
  free(v);
  return tab;
}

/* One slice (axis 2: z = 1/2, the xy plane; axis 1: y = 1/2, the xz plane)
 * of the pattern (t NULL) or of c. */
static double *slice(const nl_cheng3_table *t, const nl_cheng3_config *c,
                     const nl_cheng3_pattern *pat, int axis, int size)
{
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  for (int b = 0; b < size; b++)
    for (int a = 0; a < size; a++) {
      double u = (a + 0.5) / size, w = (b + 0.5) / size, x = u, y = axis == 2 ? w : 0.5,
             z = axis == 2 ? 0.5 : w;
      v[(size_t)b * size + a] = t ? nl_cheng3_value(t, c, x, y, z) : pattern_at(pat, x, y, z);
    }
  return v;
}

void c8_slices(const nl_cheng3_table *t, const nl_cheng3_table *t0, const nl_cheng3_config *c,
               const nl_cheng3_pattern *pat, int size, nl_image **panels, const char **labels)
{
  /* short: the labels must fit under a 64-pixel panel (the caption says the rest) */
  static const char *const lab[C8_NPANELS] = { "D xy", "c xy", "c xy str", "rand xy",
                                               "D xz", "c xz", "c xz str", "rand xz" };
  for (int row = 0; row < 2; row++) {
    int axis = row ? 1 : 2;
    double *d = slice(NULL, c, pat, axis, size); /* the pattern */
    double *v = slice(t, c, pat, axis, size);    /* the optimised table's c */
    double *v0 = slice(t0, c, pat, axis, size);  /* the random start's c */
    nl_image **p = panels + 4 * row;
    p[0] = nl_image_from_values(d, size, size, 0, 1);
    p[1] = nl_image_from_values(v, size, size, 0, 1);
    p[2] = nl_study_cheng_grey_image(v, size, size);
    p[3] = nl_study_cheng_grey_image(v0, size, size);
    free(d);
    free(v);
    free(v0);
  }
  for (int q = 0; q < C8_NPANELS; q++) labels[q] = lab[q];
}

nl_table *c8_levels_table(const nl_cheng3_table *t, const nl_cheng3_config *c, size_t *cnt)
{
  const char *lc[] = { "octave", "frequency", "lattice_points", "new_entries", "fraction_of_M" };
  nl_table *lv = nl_table_alloc(5, lc);
  nl_cheng3_level_entries(t, c, cnt);
  for (int l = 0; l < c->octaves; l++) {
    double f = c->f1 * (1 << l), np = pow(ceil(f) + 1, 3);
    nl_table_append(lv, "iddid", l + 1, f, np, (int)cnt[l], (double)cnt[l] / (double)c->m);
  }
  return lv;
}
