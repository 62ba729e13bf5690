/* S1 - Shaffer's fractal sum, sum_{j<n} noise(2^j p) / 2^j, at 1, 2, 3 and
 * 8 octaves (slide "Example", panels (a)-(d)). */
#include "s1.h"
#include "study/nl_study.h"

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("s1_fractal_sum", "S1 - Fractal sum at 1, 2, 3 and 8 octaves", argc, argv);
  nl_noise_window win = nl_study_window(r);
  nl_harness_params_done(r);

  nl_table *d = nl_study_octave_series(r, &win, 0,
                                       "2D cross sections of the fractal sum with 1, 2, 3 "
                                       "and 8 octaves (images only).",
                                       "fractal", "fractal_sum(p) = sum noise(2^j p) / 2^j");
  s1_report(r, d);
  nl_table_free(d);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
