/* report.c - S3's report prose: what the gain and the lacunarity do to
 * fBm's picture and spectrum (the slides "fBm varying gain / lacunarity"). */
#include "s3.h"

#include <math.h>
#include <stdio.h>

/* n as an English word up to ten ("six octaves"), else its digits. */
static const char *count_word(int n, char *buf, size_t size)
{
  static const char *words[] = { "zero", "one",   "two",   "three", "four", "five",
                                 "six",  "seven", "eight", "nine",  "ten" };
  if (n >= 0 && n <= 10) return words[n];
  snprintf(buf, size, "%d", n);
  return buf;
}

void s3_report_intro(nl_harness *r, int octaves, const nl_noise_window *win)
{
  nl_harness_text(
      r,
      "**Slides:** fBm with %d octaves, gain 0, 0.25, 0.5, 0.75, 1 at lacunarity 2, and "
      "lacunarity 0.5, 1, 2, 4, 8 at gain 0.5 (images only). **Ours:** the slice z = %g of "
      "Perlin's improved 3D noise over [0, %g)^2, %d seeds for the numbers.\n",
      octaves, win->z, win->size, nl_harness_seeds(r));
}

void s3_report_gain(nl_harness *r, int octaves)
{
  char buf[16];
  nl_harness_text(
      r,
      "Gain 0 is one octave of noise; each step of the gain lifts the high bands of the "
      "spectrum (power of octave j scales as gain^2j) and the sd grows as "
      "sqrt(sum gain^2j). At gain 1 all %s octaves weigh the same and the image is "
      "close to white noise at the pixel scale.\n",
      count_word(octaves, buf, sizeof buf));
}

void s3_report_lacunarity(nl_harness *r, int octaves, const nl_table *gains, const nl_table *lacs)
{
  char buf[16];
  /* Lacunarity 1 (row 1) against gain 0 (row 0): the same noise, scaled. */
  double ratio = nl_table_value(lacs, 1, "sd") / nl_table_value(gains, 0, "sd");
  double top = nl_table_value(lacs, 4, "lacunarity");
  nl_harness_text(
      r,
      "Lacunarity 1 sums one noise %s times: the picture of gain 0 at %.2f times the "
      "amplitude (sd and max in the table), with the same spectrum shape. Lacunarity "
      "0.5 adds ever larger, smoother octaves, which dominate the low end of the "
      "spectrum. Lacunarity 4 and 8 put octaves far above the pixel rate (%g^%d = %g "
      "cycles per unit): they alias to a flat floor, the grain of panels (d) and (e).\n",
      count_word(octaves, buf, sizeof buf), ratio, top, octaves - 1, pow(top, octaves - 1));
}
