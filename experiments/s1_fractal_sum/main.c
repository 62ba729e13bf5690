/* S1 - Shaffer's fractal sum, sum_{j<n} noise(2^j p) / 2^j, at 1, 2, 3 and
 * 8 octaves (slide "Example", panels (a)-(d)). */
#include "s1.h"
#include "study/nl_study.h"

#include <stdio.h>

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("s1_fractal_sum", "S1 - Fractal sum at 1, 2, 3 and 8 octaves", argc, argv);
  nl_noise_window win = nl_study_window(r);
  nl_harness_params_done(r);

  nl_table *seeds;
  nl_table *d =
      nl_study_octave_series(r, &win, 0,
                             "2D cross sections of the fractal sum with 1, 2, 3 "
                             "and 8 octaves (images only).",
                             "fractal", "fractal_sum(p) = sum noise(2^j p) / 2^j", &seeds);
  /* The slides' law against the lone octave (row 0, sd1 by construction),
   * and its negative control: the same octaves and gains with every octave
   * at the first one's frequency, one noise summed with itself. */
  const char *lone = nl_table_text(d, 0, "setting");
  nl_table *law = nl_study_sd_law_table(d, seeds, seeds, lone);
  nl_table *ctl = nl_study_sd_law_control("improved", law, seeds, lone, &win, nl_harness_seed(r),
                                          nl_harness_seeds(r));
  nl_harness_write_table(r, law, "fractal_sd_law.tsv");
  nl_harness_write_table(r, ctl, "fractal_sd_control.tsv");
  for (size_t i = 1; i < law->nrows; i++) {
    char q[96];
    snprintf(q, sizeof q, "sd of the sum over sd1 sqrt(sum 4^-j), %s",
             nl_table_text(law, i, "setting"));
    /* "equal to the law" as equivalence within the margin of
     * docs/experiments.md (Equivalence margins, S1 and S3) */
    nl_harness_verdict_equiv(r, "fractal_sd_law.tsv", law, i, q, "claim_ratio", "sd_over_law",
                             "sd_over_law_se", "seeds", NL_STUDY_SD_LAW_RULE, "independent",
                             "variances of uncorrelated octaves add; se: the standard error of "
                             "the ratio taken seed by seed");
    nl_harness_verdict_control(r,
                               "the same octaves at one frequency (one noise summed with itself)",
                               "fractal_sd_control.tsv", ctl, i);
  }
  nl_harness_verdict_figure(r, "fractal sum at 1, 2, 3 and 8 octaves",
                            "octaves add detail at half the amplitude (images only)",
                            "fractal_panels.png", NULL);
  s1_report(r, d, law);
  nl_harness_report_table(r, ctl,
                          "The law's negative control (fractal_sd_control.tsv): the same octaves "
                          "and gains all at the first octave's frequency, one noise summed with "
                          "itself, against the same law; its sd is sd1 sum 2^-j",
                          4);
  nl_table_free(law);
  nl_table_free(ctl);
  nl_table_free(seeds);
  nl_table_free(d);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
