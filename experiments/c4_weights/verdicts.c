/* C4's verdicts on Table 4.1 (Cheng 2009 sec. 4.3.2). The headline reads the
 * weights as the table prints them and runs at the run's control grid and
 * schedule, neither chosen by the thesis's numbers; the reading and the grid
 * chosen by closeness to the thesis follow as their own rows, capped by
 * their kind. */
#include "c4.h"
#include "harness/nl_harness.h"

#include <stdio.h>

void c4_verdicts(nl_harness *r, const nl_table *cmp, const nl_table *rd, const nl_table *eg,
                 const nl_table *seams, const nl_table *runs, const nl_table *trend)
{
  /* The negative control of every independent row: the unoptimised start
   * tables of the same seeds (seams.tsv's last row), whose E_KS and E_Con
   * no weight has touched. */
  size_t u = seams->nrows - 1;
  const char *ctl = "the unoptimised start tables (no weights)";
  for (size_t i = 0; i < cmp->nrows; i++) {
    char q[64];
    snprintf(q, sizeof q, "E_KS, printed weights, panel %s", nl_table_text(cmp, i, "panel"));
    nl_harness_verdict(r, "table41.tsv", cmp, i, q, "paper_E_ks", "E_ks", "E_ks_sd",
                       "factor 1.25 2", "independent", "Table 4.1's weights as printed");
    nl_harness_verdict_control(r, ctl, "seams.tsv", seams, u);
  }
  /* The reading closest on absolute scale: each panel takes the run that
   * reading gives it (mixed_a_printed: panel a printed, the rest swapped). */
  size_t sel = c4_readings_closest(rd);
  const char *name = nl_table_text(rd, sel, "reading");
  char note[96];
  snprintf(note, sizeof note, "reading %s, the closest to the thesis's E_KS of the three", name);
  for (size_t i = 0; i < cmp->nrows; i++) {
    char q[64];
    snprintf(q, sizeof q, "E_KS, closest reading, panel %s", nl_table_text(cmp, i, "panel"));
    int sw = c4_reading_swapped((int)sel, (int)i);
    nl_harness_verdict(r, "table41.tsv", cmp, i, q, "paper_E_ks", sw ? "E_ks_swapped" : "E_ks",
                       NULL, "factor 1.25 2", "selected 1/3", note);
  }
  for (size_t i = 0; i < cmp->nrows; i++) {
    char q[64];
    snprintf(q, sizeof q, "E_Con, printed weights, panel %s", nl_table_text(cmp, i, "panel"));
    nl_harness_verdict(r, "table41.tsv", cmp, i, q, "paper_E_con", "E_con", "E_con_sd",
                       "factor 1.25 2", "independent",
                       "our control grid and schedule, chosen without the thesis's numbers");
    nl_harness_verdict_control(r, ctl, "seams.tsv", seams, u);
  }
  size_t fit = c4_econ_fitted(eg);
  nl_harness_verdict(r, "econ_grid.tsv", eg, fit, "E_Con, Table 4.1 mean, grid fitted to it",
                     "paper_E_con", "E_con", NULL, "factor 1.25 2", "fitted 1/6",
                     "printed weights at the control grid whose E_Con is closest to the thesis's");
  nl_harness_verdict_p(r, "trend.tsv", trend, 0, "larger control weight keeps the pattern: r trend",
                       "the pattern can be well-preserved with larger weight in control term", "rho",
                       "p_perm", "p 0.01 0.05", "independent",
                       "Spearman's rho of r with the pattern on log(w2 / w1) over the sweep, "
                       "one-sided permutation p");
  nl_harness_verdict_control(r, "the same tables against the pattern shuffled", "trend.tsv", trend,
                             1);
  /* runs: printed rows 0, 2, ..., 10 are panels a..f */
  nl_harness_verdict_less(r, "table41_runs.tsv", runs, 0, 10,
                          "(a) keeps the pattern better than (f): E_Con",
                          "in Figure 4.8(f) the patterns do not preserve well in comparison of (a)",
                          "E_con", "E_con_sd", "seeds", 0.05, "independent");
  nl_harness_verdict_control_less(r, ctl, "seams.tsv", seams, u, u);
}
