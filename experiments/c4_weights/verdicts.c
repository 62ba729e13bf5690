/* C4's verdicts on Table 4.1 (Cheng 2009 sec. 4.3.2). The headline reads the
 * weights as the table prints them and runs at the run's control grid and
 * schedule, neither chosen by the thesis's numbers; the reading and the grid
 * chosen by closeness to the thesis follow as their own rows, capped by
 * their kind. */
#include "c4.h"
#include "harness/nl_harness.h"

#include <stdio.h>

void c4_verdicts(nl_harness *r, const nl_table *cmp, const nl_table *rd, const nl_table *eg)
{
  nl_harness_verdict_rows(r, "table41.tsv", cmp, "E_KS, printed weights", "panel", "paper_E_ks",
                          "E_ks", "E_ks_sd", "factor 1.25 2", "independent",
                          "Table 4.1's weights as printed");
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
  nl_harness_verdict_rows(r, "table41.tsv", cmp, "E_Con, printed weights", "panel", "paper_E_con",
                          "E_con", "E_con_sd", "factor 1.25 2", "independent",
                          "our control grid and schedule, chosen without the thesis's numbers");
  size_t fit = c4_econ_fitted(eg);
  nl_harness_verdict(r, "econ_grid.tsv", eg, fit, "E_Con, Table 4.1 mean, grid fitted to it",
                     "paper_E_con", "E_con", NULL, "factor 1.25 2", "fitted 1/6",
                     "printed weights at the control grid whose E_Con is closest to the thesis's");
}
