/* C9's rows: fixed against optimised octave amplitudes (Cheng 2009 ch. 5,
 * eq. 3.10) - per case the summary row, the optimised gains per octave and
 * the CPU time of one optimisation. */
#include "c9.h"
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static nl_table *labelled_alloc(int nlabels, const char *const *labels, const char *const *cols,
                                size_t ncols)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < ncols; i++) names[nlabels + (int)i] = cols[i];
  return nl_table_alloc((size_t)nlabels + ncols, names);
}

static const char *const gain_cols[] = { "octave",  "a_thesis",    "a", "a_sd",    "gain",
                                         "gain_sd", "log_gain_sd", "R", "at_bound" };
#define NGAIN (sizeof gain_cols / sizeof *gain_cols)

nl_table *c9_gains_alloc(int nlabels, const char *const *labels)
{
  return labelled_alloc(nlabels, labels, gain_cols, NGAIN);
}

static size_t labelled_row(nl_table *t, int nlabels, const char *const *labels)
{
  size_t r = nl_table_append_empty(t);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
  return r;
}

static const char *const part_cols[] = {
  "seeds",           "E_con",          "E_con_sd",          "E_con_offset",
  "E_con_offset_sd", "E_con_contrast", "E_con_contrast_sd", "E_con_shape",
  "E_con_shape_sd",  "octave1_share",  "octave1_share_sd", "one_minus_r",
  "one_minus_r_sd"
};
#define NPART (sizeof part_cols / sizeof *part_cols)

nl_table *c9_parts_alloc(int nlabels, const char *const *labels)
{
  return labelled_alloc(nlabels, labels, part_cols, NPART);
}

/* E_Con and its three parts (nl_cheng_eval): mean and sd over the k runs */
/* and octave 1's share of the summed amplitude, 1/a_1 / sum_l 1/a_l with
 * the run's gains (the thesis's: 0.53 for F = 4; near 1 when octave 1
 * carries the value alone) */
static void parts_row(nl_table *parts, int nlabels, const char *const *labels,
                      const nl_cheng_config *c, const nl_cheng_eval *evs, int k)
{
  double *x = nl_xmalloc((size_t)k * sizeof *x);
  size_t r = labelled_row(parts, nlabels, labels);
  nl_table_set(parts, r, "seeds", k);
  for (int part = 0; part < 4; part++) {
    for (int q = 0; q < k; q++)
      x[q] = part == 0   ? evs[q].e_con
             : part == 1 ? evs[q].e_con_offset
             : part == 2 ? evs[q].e_con_contrast
                         : evs[q].e_con_shape;
    nl_table_set(parts, r, part_cols[1 + 2 * part], nl_stats_mean(x, k, NL_STATS_RUNNING));
    nl_table_set(parts, r, part_cols[2 + 2 * part], nl_stats_sd(x, k, NL_STATS_RUNNING));
  }
  nl_noise_octaves o = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  for (int q = 0; q < k; q++) {
    double all = 0;
    for (int l = 0; l < c->octaves; l++) all += o.amp[l] * exp(evs[q].log_gain[l]);
    x[q] = o.amp[0] * exp(evs[q].log_gain[0]) / all;
  }
  nl_table_set(parts, r, "octave1_share", nl_stats_mean(x, k, NL_STATS_RUNNING));
  nl_table_set(parts, r, "octave1_share_sd", nl_stats_sd(x, k, NL_STATS_RUNNING));
  /* the shape alone, scale-free: 1 - r with the pattern (E_Con's shape part
   * is 2 n sd_c sd_D (1 - r), so it grows with the contrast sd_c) */
  for (int q = 0; q < k; q++) x[q] = 1 - evs[q].r_pattern;
  nl_table_set(parts, r, "one_minus_r", nl_stats_mean(x, k, NL_STATS_RUNNING));
  nl_table_set(parts, r, "one_minus_r_sd", nl_stats_sd(x, k, NL_STATS_RUNNING));
  free(x);
}

nl_table *c9_timing_alloc(int nlabels, const char *const *labels)
{
  const char *cols[] = { "seconds_per_run" };
  return labelled_alloc(nlabels, labels, cols, 1);
}

void c9_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
             const c9_tables *t, int nlabels, const char *const *labels, double *first_log_gain)
{
  int k = nl_harness_seeds(s->r);
  nl_table *gains = t->gains;
  nl_table *timing = t->timing;
  nl_study_cheng_rows_add(s, t->sum, nlabels, labels, evs);
  parts_row(t->parts, nlabels, labels, c, evs, k);
  /* Per run, the thread CPU of its optimisation (nl_cheng_eval.cpu_seconds):
   * the runs share the cores (--threads), so wall time would not be per run. */
  double cpu = 0;
  for (int q = 0; q < k; q++) cpu += evs[q].cpu_seconds;
  nl_table_set(timing, labelled_row(timing, nlabels, labels), "seconds_per_run", cpu / k);
  memcpy(first_log_gain, evs[0].log_gain, (size_t)c->octaves * sizeof *first_log_gain);
  nl_noise_octaves o = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  double *a = nl_xmalloc((size_t)k * 3 * sizeof *a); /* a_l, gain and ln gain per seed */
  double *g = a + k;
  double *u = g + k;
  double hi = log(c->amp_range);
  for (int l = 0; c->amp_vary && l < c->octaves; l++) {
    int bound = 0;
    for (int q = 0; q < k; q++) {
      u[q] = evs[q].log_gain[l];
      g[q] = exp(u[q]);
      a[q] = 1.0 / (o.amp[l] * g[q]); /* a_l = a_l^thesis / gain */
      bound += fabs(fabs(u[q]) - hi) < 1e-3;
    }
    double row[NGAIN] = { l + 1,                                 /* octave */
                          1.0 / o.amp[l],                        /* a_thesis */
                          nl_stats_mean(a, k, NL_STATS_RUNNING), /* a */
                          nl_stats_sd(a, k, NL_STATS_RUNNING),   /* a_sd */
                          nl_stats_mean(g, k, NL_STATS_RUNNING), /* gain */
                          nl_stats_sd(g, k, NL_STATS_RUNNING),   /* gain_sd */
                          nl_stats_sd(u, k, NL_STATS_RUNNING),   /* log_gain_sd */
                          c->amp_range,                          /* R */
                          (double)bound / k };                   /* at_bound */
    size_t r = labelled_row(gains, nlabels, labels);
    for (size_t i = 0; i < NGAIN; i++) nl_table_set(gains, r, gain_cols[i], row[i]);
  }
  free(a);
}

void c9_tests_add(nl_table *tests, const c9_tables *t, size_t f, const char *group,
                  const char *const *q, size_t nq)
{
  size_t o = f + 1, w = f + 2;
  const char *parts[3] = { "E_con_offset", "E_con_contrast", "E_con_shape" };
  for (size_t j = 0; j < nq; j++)
    nl_study_cheng_welch_add(tests, t->sum, o, f, q[j], group, "optimised", "fixed");
  for (int j = 0; j < 3; j++)
    nl_study_cheng_welch_add(tests, t->parts, o, f, parts[j], group, "optimised", "fixed");
  /* wide bounds against the default ones: does the optimum move with the box? */
  const char *wq[3] = { "E_con", "contrast", "r_pattern" };
  for (int j = 0; j < 3; j++)
    nl_study_cheng_welch_add(tests, t->sum, w, o, wq[j], group, "optimised_wide", "optimised");
  nl_study_cheng_welch_add(tests, t->parts, w, o, "E_con_shape", group, "optimised_wide",
                           "optimised");
}

void c9_random_gains(nl_cheng_config *c, unsigned long seed, int index)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "c9.random_gains", (unsigned long)index));
  double hi = log(c->amp_range);
  for (int l = 0; l < c->octaves; l++) c->log_gain[l] = hi * (2 * gsl_rng_uniform(rng) - 1);
  c->amp_vary = 0;
  gsl_rng_free(rng);
}

void c9_tables_write(nl_harness *r, const c9_tables *t, const c9_tables *b, const nl_table *tests)
{
  nl_harness_write_table(r, t->sum, "summary.tsv");
  nl_harness_write_table(r, t->parts, "parts.tsv");
  nl_harness_write_table(r, t->gains, "gains.tsv");
  nl_harness_write_table(r, tests, "tests.tsv");
  nl_harness_time_column(r, "timing.tsv", "seconds_per_run"); /* CPU time, not a result */
  nl_harness_write_table(r, t->timing, "timing.tsv");
  nl_harness_write_table(r, b->sum, "baselines.tsv");
  nl_harness_write_table(r, b->parts, "baselines_parts.tsv");
}

void c9_tables_free(c9_tables *t)
{
  nl_table_free(t->sum);
  nl_table_free(t->parts);
  nl_table_free(t->gains);
  nl_table_free(t->timing);
}
