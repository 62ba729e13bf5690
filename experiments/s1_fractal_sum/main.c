/* S1 - Shaffer's fractal sum, sum_{j<n} noise(2^j p) / 2^j, at 1, 2, 3 and
 * 8 octaves (slide "Example", panels (a)-(d)). */
#include "study/nl_study.h"

#include <math.h>

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("s1_fractal_sum", "S1 - Fractal sum at 1, 2, 3 and 8 octaves", argc, argv);
  nl_noise_window win = nl_study_window(r);
  nl_harness_params_done(r);

  nl_table *d = nl_study_octave_series(r, &win, 0, "2D cross sections of the fractal sum with 1, 2, 3 "
                                       "and 8 octaves (images only).", "fractal",
                                       "fractal_sum(p) = sum noise(2^j p) / 2^j");
  nl_harness_text(r, "Each octave adds a band one octave up at a quarter of the power (amplitude 1/2): "
                     "the staircase of the spectrum. The sd grows from %.4f (1 octave) to %.4f "
                     "(8 octaves), a factor %.3f; for octaves that were uncorrelated it would be "
                     "sqrt(1 + 1/4 + ... + 1/4^7) = %.3f. The largest value seen is %.0f%% of the "
                     "analytic bound at 1 octave and %.0f%% at 8: extremes of different octaves "
                     "rarely align, so the bound loosens as octaves are added.\n",
                 nl_table_value(d, 0, "sd"), nl_table_value(d, 3, "sd"), nl_table_value(d, 3, "sd") / nl_table_value(d, 0, "sd"),
                 sqrt((1 - pow(0.25, 8)) / 0.75), 100 * nl_table_value(d, 0, "max_abs_over_bound"),
                 100 * nl_table_value(d, 3, "max_abs_over_bound"));
  nl_table_free(d);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
