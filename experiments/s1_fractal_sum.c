/* S1 - Shaffer's fractal sum, sum_{j<n} noise(2^j p) / 2^j, at 1, 2, 3 and
 * 8 octaves (slide "Example", panels (a)-(d)). */
#include "study/nl_study.h"

int main(int argc, char **argv)
{
  nl_run *r = nl_run_begin("s1_fractal_sum", "S1 - Fractal sum at 1, 2, 3 and 8 octaves", argc, argv);
  int size = (int)nl_run_param_int(r, "size", nl_run_quick(r) ? 128 : 512, 16, 4096);
  double extent = nl_run_param(r, "extent", 4.0, 1e-3, 1e4);
  double z = nl_run_param(r, "z", 0.5, -1e6, 1e6);
  nl_run_params_done(r);

  nl_report_text(r, "**Slides:** 2D cross sections of the fractal sum with 1, 2, 3 and 8 octaves "
                    "(images only). **Ours:** the slice z = %g of Perlin's improved 3D noise over "
                    "[0, %g)^2, %d seeds for the numbers.\n", z, extent, nl_run_seeds(r));
  const int oct[] = {1, 2, 3, 8};
  nl_setting st[4];
  char labels[4][32];
  nl_study_octave_settings(oct, 4, 0, st, labels);
  nl_window win = {0, 0, z, extent, size, size};
  nl_study_series(r, "fractal", "fractal_sum(p) = sum noise(2^j p) / 2^j", NL_BASIS_IMPROVED3, st, 4, &win);
  nl_report_text(r, "Each octave adds a band one octave up at a quarter of the power (amplitude 1/2): "
                    "the staircase of the spectrum. The sd converges as sqrt(1 + 1/4 + 1/16 + ...) "
                    "and the largest value seen stays well inside the analytic bound, whose ratio "
                    "to the observed extreme falls as octaves are added (extremes of independent "
                    "octaves rarely align).\n");
  return nl_run_end(r);
}
