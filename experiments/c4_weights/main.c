/* C4 - Cheng 2009 Table 4.1 and Fig 4.8 (sec. 4.3.2): the weights (w1, w2)
 * of E = w1 E_KS + w2 E_Con (eq. 3.9). The six pairs of the table as printed
 * (the headline) beside the thesis's numbers, the same pairs with w1 and w2
 * swapped (what the thesis's text implies for some rows), E_Con over control
 * grids and annealing budgets (neither stated by the thesis), the seams of
 * the optimised panels, and a dense log sweep of w1 / w2 (w1 + w2 = 1) as the
 * E_KS vs E_Con trade-off curve. */
#include "c4.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NPAIR 6

/* Table 4.1 as printed: w1, E_KS, w2, E_Con. */
static const c4_thesis_row thesis[NPAIR] = {
  { 0, 0.13378, 1, 49.7715 },
  { 0.1, 0.048835, 0.9, 49.7668 },
  { 0.01, 0.072425, 0.99, 49.7946 },
  { 0.001, 0.061537, 0.999, 49.8427 },
  { 0.0001, 0.017303, 0.9999, 49.7977 },
  { 0.00001, 0.012973, 0.99999, 50.1087 },
};
static const char *const panel_name[NPAIR] = { "a", "b", "c", "d", "e", "f" };

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c4_weights",
                      "C4 - weights of the KS and control terms (Table 4.1, Fig 4.8)", &argc, argv);
  nl_harness *r = s.r;
  int quick = nl_harness_quick(r);
  int nsweep = (int)nl_harness_param_int(
      r, "sweep_points", quick ? 6 : 24, 2, 1000,
      "points of the dense E_KS / E_Con trade-off sweep over w1 / w2 (quick 6)");
  /* Log-spaced in w1 / w2 (w1 + w2 = 1): the balance lies at w1 / w2 ~ 1e2..1e3,
   * where a log w1 scale has no points. */
  double lo = nl_harness_param(r, "ratio_lo", 1e-5, 1e-12, 1e12,
                               "smallest w1 / w2 of the trade-off sweep (log-spaced, w1 + w2 = 1)");
  double hi = nl_harness_param(r, "ratio_hi", 1e5, 1e-12, 1e12,
                               "largest w1 / w2 of the trade-off sweep (log-spaced, w1 + w2 = 1)");
  /* table=0: only the run at the configured (w1, w2), the unit a sweep of
   * w1 is made of (scripts/noiselab sweep c4 --param w1=... --param table=0). */
  int table = (int)nl_harness_param_int(r, "table", 1, 0, 1,
                                        "1: Table 4.1 and the trade-off sweep; 0: only the run at "
                                        "the configured w1, w2 (a sweep's unit)");
  int gmin = (int)nl_harness_param_int(r, "grid_min", quick ? 16 : 8, 1, 1024,
                                       "smallest control grid of the E_Con grid x budget table "
                                       "(doubling up to grid_max; the run's grid is added; quick "
                                       "16)");
  int gmax =
      (int)nl_harness_param_int(r, "grid_max", quick ? 16 : 64, 1, 1024,
                                "largest control grid of the E_Con grid x budget table (quick 16)");
  double blow = nl_harness_param(
      r, "budget_low", 0.1, 1e-3, 1,
      "the short annealing budget of the E_Con table, as a fraction of moves_per_var");
  nl_study_cheng_ready(&s);
  if (!(lo < hi)) nl_harness_die(r, 2, "ratio_lo must be below ratio_hi");
  nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, "flower");
  const nl_cheng_config base = s.c;
  const char *labels[] = { "reading", "panel", "w1", "w2" };

  /* The configured weights alone. */
  nl_table *one = nl_study_cheng_summary_alloc(4, labels);
  nl_cheng_config cc = base;
  c4_case conf;
  c4_case_set(&cc, &conf, "configured", "-", base.w1, base.w2);
  nl_noise_grad2_free(nl_study_cheng_seeds(&s, &cc, pat, one, 4, conf.lab));
  nl_harness_write_table(r, one, "configured.tsv");
  if (!table) c4_configured_text(r, one, &base);
  nl_table_free(one);
  if (!table) {
    nl_cheng_pattern_free(pat);
    return nl_harness_end(r);
  }

  /* Table 4.1's pairs, printed at cases 0, 2, 4, ... and swapped at 1, 3, 5,
   * ..., then the sweep: one set of independent runs on the run's threads,
   * each case's row to its table in case order. */
  int n = 2 * NPAIR + nsweep, k = nl_harness_seeds(r);
  nl_cheng_config *cs = nl_xmalloc((size_t)n * sizeof *cs);
  const nl_cheng_pattern **pp = nl_xmalloc((size_t)n * sizeof *pp);
  nl_noise_grad2 **firsts = nl_xmalloc((size_t)n * sizeof *firsts);
  c4_case *wc = nl_xmalloc((size_t)n * sizeof *wc);
  double *rhos = nl_xmalloc((size_t)nsweep * sizeof *rhos);
  c4_cases_set(cs, wc, &base, thesis, panel_name, NPAIR, lo, hi, nsweep, rhos);
  for (int q = 0; q < n; q++) pp[q] = pat;
  nl_noise_grad2 **tables = nl_xmalloc((size_t)n * (size_t)k * sizeof *tables);
  nl_cheng_eval *evs = nl_study_cheng_runs_tables(&s, n, cs, pp, tables);
  for (int q = 0; q < n; q++) firsts[q] = tables[(size_t)q * k];
  nl_table *tab = nl_study_cheng_summary_alloc(4, labels);
  nl_table *sweep = nl_study_cheng_summary_alloc(4, labels);
  for (int q = 0; q < n; q++)
    nl_study_cheng_rows_add(&s, q < 2 * NPAIR ? tab : sweep, 4, wc[q].lab, evs + (size_t)q * k);
  c4_fig48(r, pat, firsts, NPAIR, &base);
  c4_tables_write(r, wc, firsts, 2 * NPAIR);
  c4_seams_domain(&s, cs, pat, firsts, NPAIR);
  nl_table *trend = c4_trend(&s, &base, pat, sweep, tables + (size_t)2 * NPAIR * k, rhos, nsweep);
  for (size_t q = 0; q < (size_t)n * k; q++) nl_noise_grad2_free(tables[q]);
  free(tables);
  free(cs);
  free(pp);
  free(firsts);
  free(wc);

  /* Table 4.1 ours vs thesis, and how each reading of its weights compares. */
  nl_table *cmp = c4_table41(tab, thesis, NPAIR);
  nl_harness_write_table(r, tab, "table41_runs.tsv");
  nl_harness_write_table(r, cmp, "table41.tsv");
  nl_harness_write_table(r, sweep, "sweep.tsv");
  c4_table41_text(r, cmp, s.grid, nsweep, lo, hi, pat->n);
  nl_table *rd = c4_readings(cmp, thesis, NPAIR);
  nl_harness_write_table(r, rd, "readings.tsv");
  c4_readings_text(r, rd);
  c4_reading_tests(r, tab, NPAIR);
  nl_table *st = c4_seams(&s, &base, pat, evs, NPAIR);

  /* E_Con's scale: the printed and swapped pairs over grids and budgets. */
  nl_table *er = c4_econ_runs(&s, &base, "flower", thesis, NPAIR, evs, gmin, gmax, blow);
  free(evs);
  nl_table *eg = c4_econ_grid(er, thesis, NPAIR, base.sched.moves_per_var);
  nl_harness_write_table(r, er, "econ_grid_runs.tsv");
  nl_harness_write_table(r, eg, "econ_grid.tsv");
  c4_econ_text(r, eg, &base, s.grid, blow);
  c4_verdicts(r, cmp, rd, eg, st, tab, trend);
  nl_table_free(st);
  nl_table_free(trend);
  c4_uniformity_text(r, tab, sweep, rhos, NPAIR);
  c4_figures_text(r, thesis, NPAIR, sweep);
  nl_cheng_pattern_free(pat);
  free(rhos);
  nl_study_cheng_control_text(r, tab, 4);
  nl_table_free(tab);
  nl_table_free(sweep);
  nl_table_free(cmp);
  nl_table_free(rd);
  nl_table_free(er);
  nl_table_free(eg);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
