/* report.c - S1's report prose: the fractal sum's staircase spectrum, its
 * sd against uncorrelated octaves, and the bound, from the run's tables. */
#include "s1.h"
#include "study/nl_study.h"

void s1_report(nl_harness *r, const nl_table *d, const nl_table *law)
{
  int top = (int)nl_table_value(d, 3, "octaves");
  double sd1 = nl_table_value(d, 0, "sd");
  double sdn = nl_table_value(d, 3, "sd");
  nl_harness_report_table(r, law,
                          "The sd of the sum against the slides' law for uncorrelated octaves "
                          "(fractal_sd_law.tsv)",
                          4);
  nl_study_sd_law_text(r, law);
  nl_harness_text(
      r,
      "Each octave adds a band one octave up at a quarter of the power (amplitude 1/2): the "
      "staircase of the spectrum. The sd grows from %.4f (1 octave) to %.4f (%d octaves), a factor "
      "%.3f; for uncorrelated octaves the variances add, sqrt(1 + 1/4 + ... + 1/4^%d) = %.3f "
      "(sd_over_law %.3f +- %.3f, the standard error over seeds). The largest value seen is %.0f%% "
      "of the analytic bound at 1 octave and "
      "%.0f%% at %d: extremes of different octaves rarely align, so the bound loosens as octaves "
      "are added. The verdicts read the slides' law as stated, with sd1 the lone first octave's sd "
      "on "
      "the same slice and seeds: nothing is fitted.\n",
      sd1, sdn, top, sdn / sd1, top - 1, nl_table_value(law, 3, "sd_law") / sd1,
      nl_table_value(law, 3, "sd_over_law"), nl_table_value(law, 3, "sd_over_law_se"),
      100 * nl_table_value(d, 0, "max_abs_over_bound"),
      100 * nl_table_value(d, 3, "max_abs_over_bound"), top);
}
