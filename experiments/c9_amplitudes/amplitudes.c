/* C9 (X6): fixed against optimised octave amplitudes - runs over seeds with
 * the optimised gains kept, the gains table, the between-condition tests and
 * the prose, all formatted from the computed tables. */
#include "amplitudes.h"
#include "study/nl_study_cheng.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static nl_table *labelled_alloc(int nlabels, const char *const *labels, const char *const *cols, size_t ncols)
{
  const char *names[32];
  for (int i = 0; i < nlabels; i++) names[i] = labels[i];
  for (size_t i = 0; i < ncols; i++) names[nlabels + (int)i] = cols[i];
  return nl_table_alloc((size_t)nlabels + ncols, names);
}

static const char *const gain_cols[] = {"octave", "a_thesis", "a", "a_sd", "gain", "gain_sd", "log_gain_sd", "R", "at_bound"};
#define NGAIN (sizeof gain_cols / sizeof *gain_cols)

nl_table *nl_study_cheng_gains_alloc(int nlabels, const char *const *labels)
{
  return labelled_alloc(nlabels, labels, gain_cols, NGAIN);
}

nl_table *nl_study_cheng_timing_alloc(int nlabels, const char *const *labels)
{
  const char *cols[] = {"seconds_per_run"};
  return labelled_alloc(nlabels, labels, cols, 1);
}

static size_t labelled_row(nl_table *t, int nlabels, const char *const *labels)
{
  size_t r = nl_table_append_empty(t);
  for (int i = 0; i < nlabels; i++) nl_table_set_text(t, r, t->names[i], labels[i]);
  return r;
}

void nl_study_cheng_amp_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
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
  double *a = nl_xmalloc((size_t)k * 3 * sizeof *a), *g = a + k, *u = g + k, hi = log(c->amp_range);
  for (int l = 0; c->amp_vary && l < c->octaves; l++) {
    int bound = 0;
    for (int q = 0; q < k; q++) {
      u[q] = evs[q].log_gain[l];
      g[q] = exp(u[q]);
      a[q] = 1.0 / (o.amp[l] * g[q]);   /* a_l = a_l^thesis / gain */
      bound += fabs(fabs(u[q]) - hi) < 1e-3;
    }
    double row[NGAIN] = {l + 1, 1.0 / o.amp[l], nl_study_mean(a, k), nl_study_sd(a, k), nl_study_mean(g, k),
                         nl_study_sd(g, k), nl_study_sd(u, k), c->amp_range, (double)bound / k};
    size_t r = labelled_row(gains, nlabels, labels);
    for (size_t i = 0; i < NGAIN; i++) nl_table_set(gains, r, gain_cols[i], row[i]);
  }
  free(a);
}

static void range_of(const nl_table *t, const char *col, size_t r0, size_t step, double *lo, double *hi)
{
  *lo = INFINITY; *hi = -INFINITY;
  for (size_t q = r0; q < t->nrows; q += step) { *lo = fmin(*lo, nl_table_value(t, q, col)); *hi = fmax(*hi, nl_table_value(t, q, col)); }
}

void nl_study_cheng_amp_text(nl_harness *r, const nl_table *sum, const nl_table *tests, const nl_table *gains, double range)
{
  size_t ncase = sum->nrows / 2;
  int lower = 0, higher = 0, ks_diff = 0;
  double dlo = INFINITY, dhi = -INFINITY, kmax = 0;
  for (size_t q = 0; q < tests->nrows; q++) {
    char buf[32];
    const char *qty = nl_table_cell_text(tests, q, 1, buf);
    double p = nl_table_value(tests, q, "p_welch"), d = nl_table_value(tests, q, "diff_pct");
    if (!strcmp(qty, "E_con")) {
      lower += p < 0.05 && d < 0; higher += p < 0.05 && d > 0;
      dlo = fmin(dlo, d); dhi = fmax(dhi, d);
    } else if (!strcmp(qty, "E_ks")) {
      ks_diff += p < 0.05;
      if (fabs(d) > fabs(kmax)) kmax = d;
    }
  }
  double rf[2], ro[2], cf[2], co[2], bf = 0;
  range_of(sum, "r_pattern", 0, 2, rf, rf + 1); range_of(sum, "r_pattern", 1, 2, ro, ro + 1);
  range_of(sum, "contrast", 0, 2, cf, cf + 1); range_of(sum, "contrast", 1, 2, co, co + 1);
  for (size_t q = 0; q < gains->nrows; q++) bf += nl_table_value(gains, q, "at_bound") / (double)gains->nrows;
  nl_harness_text(r, "**Fixed vs optimised amplitudes** (%zu cases, %g seeds each, Welch's t-test at 0.05): the optimised "
                     "amplitudes lower E_Con in %d of the cases and raise it in %d (change of the mean %+.1f%% .. %+.1f%%); E_KS "
                     "differs in %d of the cases (largest change of the mean %+.1f%%). r with the pattern: fixed %.2f..%.2f, "
                     "optimised %.2f..%.2f; contrast (sd of c): fixed %.3f..%.3f, optimised %.3f..%.3f. Gains end at a "
                     "bound (1/%g or %g) in %.0f%% of octave-seeds.\n",
                  ncase, nl_table_value(sum, 0, "seeds"), lower, higher, dlo, dhi, ks_diff, kmax, rf[0], rf[1], ro[0], ro[1],
                  cf[0], cf[1], co[0], co[1], range, range, 100 * bf);
  for (size_t i = 0; i < ncase; i++) {
    char tb[32], pb[32], gl[160] = "", want[72];
    const char *t = nl_table_cell_text(sum, 2 * i, 0, tb), *p = nl_table_cell_text(sum, 2 * i, 1, pb);
    snprintf(want, sizeof want, "%s/%s", t, p);
    double pe = NAN;
    for (size_t q = 0; q < tests->nrows; q++) {
      char gb[32], qb[32];
      if (!strcmp(nl_table_cell_text(tests, q, 0, gb), want) && !strcmp(nl_table_cell_text(tests, q, 1, qb), "E_con"))
        pe = nl_table_value(tests, q, "p_welch");
    }
    for (size_t q = 0, n = 0; q < gains->nrows; q++) {
      char gt[32], gp[32];
      if (strcmp(nl_table_cell_text(gains, q, 0, gt), t) || strcmp(nl_table_cell_text(gains, q, 1, gp), p)) continue;
      snprintf(gl + strlen(gl), sizeof gl - strlen(gl), "%s%.2f", n++ ? ", " : "", nl_table_value(gains, q, "gain"));
    }
    size_t f = 2 * i, o = f + 1;
    nl_harness_text(r, "- %s/%s: E_Con %.4g +- %.3g -> %.4g +- %.3g (p = %.2g; best constant %.4g), r %.2f -> %.2f, contrast "
                       "%.3f -> %.3f, E_KS %.4f -> %.4f; mean gains per octave %s.\n",
                    t, p, nl_table_value(sum, f, "E_con"), nl_table_value(sum, f, "E_con_sd"), nl_table_value(sum, o, "E_con"),
                    nl_table_value(sum, o, "E_con_sd"), pe, nl_table_value(sum, f, "E_con_const"),
                    nl_table_value(sum, f, "r_pattern"), nl_table_value(sum, o, "r_pattern"), nl_table_value(sum, f, "contrast"),
                    nl_table_value(sum, o, "contrast"), nl_table_value(sum, f, "E_ks"), nl_table_value(sum, o, "E_ks"), gl);
  }
}
