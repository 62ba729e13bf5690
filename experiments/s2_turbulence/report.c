/* report.c - S2's report prose: how |noise| folds each octave, from the
 * run's fold table. */
#include "s2.h"

void s2_report(nl_harness *r, const nl_table *fold, double cut)
{
  nl_harness_report_table(r, fold,
                          "One octave (frequency 1) before and after the fold: mean, the DC "
                          "term's share of the power, the share of the rest above the cut "
                          "(mean over seeds, fold.tsv)",
                          4);
  nl_harness_text(
      r,
      "The absolute value folds each octave at its zero set, the dark creases. Folding moves "
      "power into the DC term (the mean goes from %.3f to %.3f; the DC term holds %.0f%% of the "
      "power of |noise|, %.1f%% of noise's) and above the octave's band (above %g cycles per unit: "
      "%.1f%% of the non-DC power of |noise| against %.1f%% of noise's, %.1f times as much): the "
      "creases are sharper than any feature of the octave itself.\n",
      nl_table_value(fold, 0, "mean"), nl_table_value(fold, 1, "mean"),
      100 * nl_table_value(fold, 1, "dc_frac"), 100 * nl_table_value(fold, 0, "dc_frac"), cut,
      100 * nl_table_value(fold, 1, "above_frac"), 100 * nl_table_value(fold, 0, "above_frac"),
      nl_table_value(fold, 1, "above_frac") / nl_table_value(fold, 0, "above_frac"));
}
