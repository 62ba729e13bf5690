/* report.c - Q3's report prose: Qin & Yang 2000 Fig. 4's fractal bump
 * wrinkles and how we shade them. */
#include "q3.h"

#include <stdio.h>

void q3_report(nl_harness *r, double extent, double k, double amp, const double light[3],
               int max_oct, const nl_table *t, const nl_table *cen)
{
  nl_harness_text(
      r,
      "**Paper (Fig. 4, eq. 6):** fractal(x) = sum_{i=0}^{octaves} |0.5 - GCTBF(2^i x)| / 2^i, "
      "bump = fractal^3, x <- x - bump N, GCTBF = F2 - F1 - F1F1, octaves 0..4 after the original "
      "(images only). **Ours:** the plane z = 0.5 over [0, %g)^2 with the pattern scaled by k = %g "
      "(eq. 5's example), lambda = 4, inverse-CDF counts; the displacement is amp = %g times bump "
      "(the paper's object size is unknown; with amp = 1 on this window the steepest slope, "
      "slope_max, would reach %.1f at %d octaves, %.2f at amp = %g), and the height field is "
      "shaded by Lambert's law under one light "
      "(%.3g, %.3g, %.3g), normals by central differences. The first row of the table (octaves = "
      "-1) is the flat original. %d seeds.\n",
      extent, k, amp, nl_table_value(t, t->nrows - 1, "slope_max"), max_oct,
      amp * nl_table_value(t, t->nrows - 1, "slope_max"), amp, light[0], light[1], light[2],
      nl_harness_seeds(r));
  nl_harness_report_table(r, t,
                          "Bump height and shading (mean over seeds; bump_max the largest, "
                          "slope_max the steepest |grad bump| at amp = 1)",
                          4);
  nl_harness_report_table(r, cen,
                          "Spectral centroid of the bump height in cycles per unit "
                          "(centroid.tsv, mean over seeds): eq. 6 at octaves 0..%d, then the last "
                          "with every octave at scale k (the control)",
                          4);
  nl_harness_text(r,
                  "Each octave of eq. 6 adds wrinkles at twice the frequency: the centroid of "
                  "the bump's power moves from %.3f to %.3f cycles per unit between octaves 0 "
                  "and %d. Summed at one scale, the same octaves only scale the bump (%.3f): "
                  "the fineness comes from the 2^i.\n",
                  nl_table_value(cen, 0, "centroid"), nl_table_value(cen, (size_t)max_oct, "centroid"),
                  max_oct, nl_table_value(cen, (size_t)max_oct + 1, "centroid"));
  char caption[64];
  snprintf(caption, sizeof caption, "Fig. 4: original plane, then octaves 0..%d", max_oct);
  nl_harness_figure(r, "bumps.png", caption);
  nl_harness_verdict_figure(r, "Fig. 4: fractal bump wrinkles, octaves 0 to 4",
                            "wrinkles grow finer with each octave (images only)", "bumps.png",
                            "our amplitude and light: the paper gives neither");
}
