/* S2 - Shaffer's turbulence (Perlin 1985), sum_{j<n} |noise(2^j p)| / 2^j,
 * at 1, 2, 3 and 8 octaves (slide "Turbulence", panels (a)-(d)). */
#include "s2.h"
#include "study/nl_study.h"

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("s2_turbulence", "S2 - Turbulence at 1, 2, 3 and 8 octaves", argc, argv);
  nl_noise_window win = nl_study_window(r);
  nl_harness_params_done(r);

  nl_table *d = nl_study_octave_series(r, &win, 1,
                                       "turbulence, the fractal sum of |noise|, at 1, 2, 3 "
                                       "and 8 octaves (images only).",
                                       "turbulence", "turbulence(p) = sum |noise(2^j p)| / 2^j");
  nl_table_free(d);
  s2_report(r);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
