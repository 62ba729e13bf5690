/* S3 - fBm(p) = sum_{j<n} gain^j noise(lacunarity^j p): gain 0, 0.25, 0.5,
 * 0.75, 1 at six octaves and lacunarity 2; lacunarity 0.5, 1, 2, 4, 8 at
 * gain 0.5 (slides "fBm varying gain / lacunarity", panels (a)-(e)). */
#include "study/nl_study.h"

#include <stdio.h>

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("s3_fbm", "S3 - fBm: gain and lacunarity", argc, argv);
  nl_noise_window win = nl_study_window(r);
  int octaves = (int)nl_harness_param_int(r, "octaves", 6, 1, 30, "octaves summed in each fBm");
  nl_harness_params_done(r);

  nl_harness_text(r, "**Slides:** fBm with %d octaves, gain 0, 0.25, 0.5, 0.75, 1 at lacunarity 2, and "
                     "lacunarity 0.5, 1, 2, 4, 8 at gain 0.5 (images only). **Ours:** the slice z = %g of "
                     "Perlin's improved 3D noise over [0, %g)^2, %d seeds for the numbers.\n",
                 octaves, win.z, win.size, nl_harness_seeds(r));
  const double gains[] = {0, 0.25, 0.5, 0.75, 1.0}, lacs[] = {0.5, 1, 2, 4, 8};
  nl_study_setting g[5], l[5];
  char gl[5][32], ll[5][32];
  for (int i = 0; i < 5; i++) {
    snprintf(gl[i], 32, "(%c) gain %g", 'a' + i, gains[i]);
    snprintf(ll[i], 32, "(%c) lacunarity %g", 'a' + i, lacs[i]);
    g[i] = (nl_study_setting){gl[i], nl_noise_octaves_fbm(octaves, gains[i], 2.0), gains[i], 2.0};
    l[i] = (nl_study_setting){ll[i], nl_noise_octaves_fbm(octaves, 0.5, lacs[i]), 0.5, lacs[i]};
  }
  nl_harness_text(r, "### Varying the gain\n");
  nl_table_free(nl_study_series(r, "gain", "fBm, lacunarity 2: gain 0, 0.25, 0.5, 0.75, 1", NL_BASIS_IMPROVED3, g, 5, &win));
  nl_harness_text(r, "Gain 0 is one octave of noise; each step of the gain lifts the high bands of the "
                     "spectrum (power of octave j scales as gain^2j) and the sd grows as "
                     "sqrt(sum gain^2j). At gain 1 all six octaves weigh the same and the image is "
                     "close to white noise at the pixel scale.\n");
  nl_harness_text(r, "### Varying the lacunarity\n");
  nl_table_free(nl_study_series(r, "lacunarity", "fBm, gain 0.5: lacunarity 0.5, 1, 2, 4, 8", NL_BASIS_IMPROVED3, l, 5, &win));
  nl_harness_text(r, "Lacunarity 1 sums one noise six times: the picture of gain 0 at 1.97 times the "
                     "amplitude (sd and max in the table), with the same spectrum shape. Lacunarity "
                     "0.5 adds ever larger, smoother octaves, which dominate the low end of the "
                     "spectrum. Lacunarity 4 and 8 put octaves far above the pixel rate (8^5 = 32768 "
                     "cycles per unit): they alias to a flat floor, the grain of panels (d) and (e).\n");
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
