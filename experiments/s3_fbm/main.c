/* S3 - fBm(p) = sum_{j<n} gain^j noise(lacunarity^j p): gain 0, 0.25, 0.5,
 * 0.75, 1 at n octaves (six by default) and lacunarity 2; lacunarity 0.5, 1,
 * 2, 4, 8 at gain 0.5 (slides "fBm varying gain / lacunarity", panels
 * (a)-(e)). */
#include "s3.h"
#include "study/nl_study.h"

#include <stdio.h>

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("s3_fbm", "S3 - fBm: gain and lacunarity", argc, argv);
  nl_noise_window win = nl_study_window(r);
  int octaves = (int)nl_harness_param_int(r, "octaves", 6, 1, 30, "octaves summed in each fBm");
  nl_harness_params_done(r);

  s3_report_intro(r, octaves, &win);
  const double gains[] = { 0, 0.25, 0.5, 0.75, 1.0 };
  const double lacs[] = { 0.5, 1, 2, 4, 8 };
  nl_study_setting g[5];
  nl_study_setting l[5];
  char gl[5][32];
  char ll[5][32];
  for (int i = 0; i < 5; i++) {
    snprintf(gl[i], 32, "(%c) gain %g", 'a' + i, gains[i]);
    snprintf(ll[i], 32, "(%c) lacunarity %g", 'a' + i, lacs[i]);
    g[i] = (nl_study_setting){ gl[i], nl_noise_octaves_fbm(octaves, gains[i], 2.0), gains[i], 2.0 };
    l[i] = (nl_study_setting){ ll[i], nl_noise_octaves_fbm(octaves, 0.5, lacs[i]), 0.5, lacs[i] };
  }
  nl_harness_text(r, "### Varying the gain\n");
  nl_table *gs;
  nl_table *ls;
  nl_table *gt = nl_study_series(r, "gain", "fBm, lacunarity 2: gain 0, 0.25, 0.5, 0.75, 1",
                                 "improved", g, 5, &win, &gs);
  /* The slides' sd law against the lone octave: gain 0 (row 0, sd1). */
  const char *lone = nl_table_text(gt, 0, "setting");
  nl_table *gsd = nl_study_sd_law_table(gt, gs, gs, lone);
  nl_harness_write_table(r, gsd, "gain_sd_law.tsv");
  /* The law's negative control: each row's octaves at one frequency. */
  unsigned long seed0 = nl_harness_seed(r);
  int nseeds = nl_harness_seeds(r);
  nl_table *gctl = nl_study_sd_law_control("improved", gsd, gs, lone, &win, seed0, nseeds);
  nl_harness_write_table(r, gctl, "gain_sd_control.tsv");
  s3_sd_verdicts(r, gsd, "gain_sd_law.tsv", gctl, "gain_sd_control.tsv", -1);
  s3_report_gain(r, octaves, gsd, "gain_spectrum.tsv");
  nl_harness_text(r, "### Varying the lacunarity\n");
  nl_table *lt = nl_study_series(r, "lacunarity", "fBm, gain 0.5: lacunarity 0.5, 1, 2, 4, 8",
                                 "improved", l, 5, &win, &ls);
  nl_table *lsd = nl_study_sd_law_table(lt, ls, gs, lone);
  nl_harness_write_table(r, lsd, "lacunarity_sd_law.tsv");
  nl_table *lctl = nl_study_sd_law_control("improved", lsd, gs, lone, &win, seed0, nseeds);
  nl_harness_write_table(r, lctl, "lacunarity_sd_control.tsv");
  s3_sd_verdicts(r, lsd, "lacunarity_sd_law.tsv", lctl, "lacunarity_sd_control.tsv",
                 2); /* lacunarity 2: gain 0.5's row */
  s3_report_lacunarity(r, octaves, lsd, &win);
  nl_harness_report_table(r, gctl,
                          "The law's negative control for the gains (gain_sd_control.tsv): each "
                          "row's octaves all at the first one's frequency, one noise summed with "
                          "itself, against the same law; its sd is sd1 sum gain^j",
                          4);
  nl_harness_verdict_figure(r, "fBm varying the gain", "higher gain, rougher fBm (images only)",
                            "gain_panels.png", NULL);
  nl_harness_verdict_figure(r, "fBm varying the lacunarity",
                            "higher lacunarity, finer detail (images only)",
                            "lacunarity_panels.png", NULL);
  nl_table_free(gt);
  nl_table_free(lt);
  nl_table_free(gsd);
  nl_table_free(gs);
  nl_table_free(ls);
  nl_table_free(lsd);
  nl_table_free(gctl);
  nl_table_free(lctl);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
