/* report.c - Q2's report prose: Qin & Yang 2000 Fig. 2's colour mapping
 * and the value range its clamp sees. */
#include "q2.h"

void q2_report(nl_harness *r, const nl_noise_window *win, const nl_noise_window *pwin,
               double perlin_freq, const nl_table *t, const nl_table *groups)
{
  nl_harness_text(
      r,
      "**Paper (Fig. 2):** eq. 4 with the 13 blue-marble knots of sec. 4.1, Perlin noise and five "
      "GCTBF combinations (images only; the combinations are drawn in the figure, not named in the "
      "text). **Ours:** the plane z = %g over [0, %g)^2 (Perlin's: z = %.4g, a third of a cell "
      "off the lattice planes, where its gradients would line up with the axes, for a frequency a "
      "power of 2), lambda = 4 with inverse-CDF counts, "
      "Ebert's Catmull-Rom spline (knots 1 and 13 only steer the ends), Perlin as RenderMan's 0.5 "
      "+ 0.5 noise at frequency %g. Combinations chosen: F1, F2 - F1 (Worley's linear ones), F1F2, "
      "F2 - F1 - F1F1, F1F2 + F2F3. The table gives the value range that the clamp to [0, 1] sees "
      "(mean over %d seeds).\n",
      win->z, win->size, pwin->z, perlin_freq, nl_harness_seeds(r));
  nl_harness_report_table(r, t, "GCTBF values before the clamp", 4);
  nl_harness_figure(r, "colour.png",
                    "Fig. 2: Perlin noise and five GCTBF combinations through the 13-knot spline");
  nl_harness_report_table(r, groups,
                          "What eq. 4 makes of each pattern (spline_use.tsv): the share clamped to "
                          "an end colour, and the entropy in bits of the colour index over the "
                          "spline's 10 segments (log2 10 = 3.32 when all are used alike); the first "
                          "rows average Worley's linear patterns and the non-linear ones per seed",
                          4);
  nl_harness_text(
      r,
      "Sec. 4.1 says the non-linear combinations give more interesting patterns than the linear "
      "ones. As a number: how many of the knots' colours a pattern draws on, the colour-index "
      "entropy. The linear patterns read %.3f bits, the non-linear ones %.3f (mean over seeds), "
      "and the non-linear F2 - F1 - F1F1 leaves %.0f%% of its pixels clamped to the first knot's "
      "colour (it is negative there). The control compares the linear patterns with themselves "
      "on other seeds (%.3f bits). The entropy counts colours, not their arrangement: it cannot "
      "see the cells' shapes, which the figure shows.\n",
      nl_table_value(groups, 0, "entropy"), nl_table_value(groups, 1, "entropy"),
      100 * nl_table_value(groups, 7, "clamped"), nl_table_value(groups, 2, "entropy"));
  nl_harness_verdict_figure(r, "Fig. 2: colour-mapped Perlin and GCTBF patterns",
                            "blue-marble patterns through the 13-knot spline (images only)",
                            "colour.png",
                            "the five combinations are our reading; no number of the paper");
}
