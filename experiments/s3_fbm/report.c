/* report.c - S3's report prose and verdicts: what the gain and the
 * lacunarity do to fBm's picture, sd and spectrum (the slides "fBm varying
 * gain / lacunarity"). */
#include "s3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

void s3_sd_verdicts(nl_harness *r, const nl_table *law, const char *file, const nl_table *ctl,
                    const char *ctl_file, long skip)
{
  for (size_t i = 0; i < law->nrows; i++) {
    if ((long)i == skip) continue;
    if (!strcmp(nl_table_text(law, i, "law"), "identical")) continue;
    if (nl_table_value(law, i, "gain") == 0) continue;
    char q[96];
    snprintf(q, sizeof q, "sd of fBm over sd1 sqrt(sum gain^2j), %s",
             nl_table_text(law, i, "setting"));
    /* "equal to the law" as equivalence within the margin of
     * docs/experiments.md (Equivalence margins, S1 and S3) */
    nl_harness_verdict_equiv(r, file, law, i, q, "claim_ratio", "sd_over_law", "sd_over_law_se",
                             "seeds", NL_STUDY_SD_LAW_RULE, "independent",
                             "variances of uncorrelated octaves add; se: the standard error of the "
                             "ratio taken seed by seed");
    nl_harness_verdict_control(r, "the same octaves at one frequency (one noise summed with itself)",
                               ctl_file, ctl, i);
  }
}

/* Least-squares slope of log power on log frequency over [lo, hi] cycles
 * per unit, column col of the spectrum table in the run's folder. */
static double spectrum_slope(nl_harness *r, const char *file, const char *col, double lo, double hi)
{
  char *path = nl_harness_path(r, file);
  nl_table *t;
  nl_error err;
  if (nl_table_read(path, 0, &t, &err)) nl_harness_die(r, 1, "%s", err.msg);
  free(path);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < t->nrows; i++) {
    double f = nl_table_value(t, i, "freq");
    if (f < lo || f > hi) continue;
    double x = log(f), y = log(nl_table_value(t, i, col));
    n++;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  nl_table_free(t);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void s3_report_gain(nl_harness *r, int octaves, const nl_table *law, const char *spectrum)
{
  char buf[16];
  size_t top = law->nrows - 1;
  nl_harness_report_table(r, law,
                          "The sd of fBm against the slides' law (gain_sd_law.tsv): sd1 the lone "
                          "octave's (gain 0)",
                          4);
  nl_study_sd_law_text(r, law);
  double slope = spectrum_slope(r, spectrum, nl_table_text(law, top, "setting"), 1, 8);
  double lo = INFINITY, hi = -INFINITY;
  for (size_t i = 1; i < law->nrows; i++) {
    lo = fmin(lo, nl_table_value(law, i, "sd_over_law"));
    hi = fmax(hi, nl_table_value(law, i, "sd_over_law"));
  }
  nl_harness_text(
      r,
      "Gain 0 is one octave of noise; each step of the gain lifts the high bands of the "
      "spectrum (power of octave j scales as gain^2j) and the sd grows as sqrt(sum gain^2j) "
      "for uncorrelated octaves: the sd over the law, sd_over_law, lies between %.3f and %.3f "
      "for gains above 0 (table). At gain %g all %s octaves weigh the same: the spectrum falls as "
      "f^%.2f over 1 "
      "to 8 cycles per unit, fBm's f^-(2H+2) with H = 0 being f^-2. The verdicts read the slides' "
      "law as "
      "stated, with sd1 the lone first octave's sd (gain 0) on the same slice and seeds: nothing "
      "is fitted.\n",
      lo, hi, nl_table_value(law, top, "gain"), count_word(octaves, buf, sizeof buf), slope);
}

void s3_report_lacunarity(nl_harness *r, int octaves, const nl_table *law,
                          const nl_noise_window *win)
{
  char buf[16];
  /* Row 1 is lacunarity 1: one noise summed, the amplitudes add. */
  double lo = nl_table_value(law, 0, "lacunarity");
  double top = nl_table_value(law, 4, "lacunarity");
  double nyq = 0.5 * win->w / win->size;
  /* The share of the variance in octaves above the pixel rate, from the
   * amplitudes (uncorrelated octaves), for lacunarity 4 and 8. */
  double share[2];
  for (int k = 0; k < 2; k++) {
    double lac = nl_table_value(law, 3 + k, "lacunarity"), g = nl_table_value(law, 3 + k, "gain");
    double all = 0, above = 0, a = 1, f = 1;
    for (int j = 0; j < octaves; j++, a *= g, f *= lac) {
      all += a * a;
      if (f > nyq) above += a * a;
    }
    share[k] = above / all;
  }
  nl_harness_report_table(r, law,
                          "The sd of fBm against the slides' law (lacunarity_sd_law.tsv): sd1 "
                          "the lone octave's (gain series, gain 0); at lacunarity 1 the octaves "
                          "are one noise and the amplitudes add",
                          4);
  nl_study_sd_law_text(r, law);
  nl_harness_text(
      r,
      "Lacunarity 1 sums one noise %s times: the picture of gain 0 at sd %.4f, %.4f times its "
      "sd, which is sum gain^j = %.4f by construction, with the same spectrum shape. Lacunarity "
      "%g adds ever larger, smoother octaves, down to %g cycles per unit. Lacunarity 4 and 8 put "
      "octaves above the pixel rate (%g cycles per unit; the top octave at %g^%d = %g): by their "
      "amplitudes %.1f%% and %.1f%% of the variance, folded back below the pixel rate.\n",
      count_word(octaves, buf, sizeof buf), nl_table_value(law, 1, "sd"),
      nl_table_value(law, 1, "sd") / nl_table_value(law, 1, "sd1"),
      nl_table_value(law, 1, "sd_law") / nl_table_value(law, 1, "sd1"), lo, pow(lo, octaves - 1),
      nyq, top, octaves - 1, pow(top, octaves - 1), 100 * share[0], 100 * share[1]);
}
