/* C9's rows: fixed against optimised octave amplitudes (Cheng 2009 ch. 5,
 * eq. 3.10) - per case the summary row, the optimised gains per octave and
 * the CPU time of one optimisation. */
#include "c9.h"
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"

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

nl_table *c9_timing_alloc(int nlabels, const char *const *labels)
{
  const char *cols[] = { "seconds_per_run" };
  return labelled_alloc(nlabels, labels, cols, 1);
}

static size_t labelled_row(nl_table *t, int nlabels, const char *const *labels)
{
  size_t r = nl_table_append_empty(t);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
  return r;
}

void c9_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
             nl_table *sum, nl_table *gains, nl_table *timing, int nlabels,
             const char *const *labels, double *first_log_gain)
{
  int k = nl_harness_seeds(s->r);
  nl_study_cheng_rows_add(s, sum, nlabels, labels, evs);
  /* Per run, the thread CPU of its optimisation (nl_cheng_eval.cpu_seconds):
   * the runs share the cores (--threads), so wall time would not be per run. */
  double cpu = 0;
  for (int q = 0; q < k; q++) cpu += evs[q].cpu_seconds;
  nl_table_set(timing, labelled_row(timing, nlabels, labels), "seconds_per_run", cpu / k);
  memcpy(first_log_gain, evs[0].log_gain, (size_t)c->octaves * sizeof *first_log_gain);
  nl_noise_octaves o = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  double *a = nl_xmalloc((size_t)k * 3 * sizeof *a);   /* a_l, gain and ln gain per seed */
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
