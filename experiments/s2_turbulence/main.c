/* S2 - Shaffer's turbulence (Perlin 1985), sum_{j<n} |noise(2^j p)| / 2^j,
 * at 1, 2, 3 and 8 octaves (slide "Turbulence", panels (a)-(d)). */
#include "fold.h"
#include "s2.h"
#include "study/nl_study.h"

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("s2_turbulence", "S2 - Turbulence at 1, 2, 3 and 8 octaves", argc, argv);
  nl_noise_window win = nl_study_window(r);
  nl_harness_params_done(r);

  nl_table *d =
      nl_study_octave_series(r, &win, 1,
                             "turbulence, the fractal sum of |noise|, at 1, 2, 3 "
                             "and 8 octaves (images only).",
                             "turbulence", "turbulence(p) = sum |noise(2^j p)| / 2^j", NULL);
  nl_table_free(d);
  /* Above twice the octave's frequency (1 cycle per unit): outside its band. */
  nl_table *fold = s2_fold_table(&win, nl_harness_seed(r), nl_harness_seeds(r), 2.0);
  nl_harness_write_table(r, fold, "fold.tsv");
  nl_harness_check(r, "fold.tsv", "mean", "welch mean_sd 1e-3");
  nl_harness_check(r, "fold.tsv", "above_frac", "welch above_frac_sd 1e-3");
  /* The slide's creases as a number: |noise| holds more of its power above
   * the octave's band than noise does (Welch over seeds); the control
   * compares noise with noise of other seeds, no fold on either side. */
  nl_harness_verdict_less(r, "fold.tsv", fold, 0, 1,
                          "power above twice the octave's frequency, noise below |noise|",
                          "|noise| folds each octave into creases sharper than the octave",
                          "above_frac", "above_frac_sd", "seeds", 0.01, "independent");
  nl_harness_verdict_control_less(r, "noise against noise of other seeds (no fold)", "fold.tsv",
                                  fold, 0, 2);
  nl_harness_verdict_figure(r, "turbulence at 1, 2, 3 and 8 octaves",
                            "|noise| folds each octave into creases (images only)",
                            "turbulence_panels.png", NULL);
  s2_report(r, fold, 2.0);
  nl_table_free(fold);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
