/* report.c - Q2's report prose: Qin & Yang 2000 Fig. 2's colour mapping
 * and the value range its clamp sees. */
#include "q2.h"

void q2_report(nl_harness *r, const nl_noise_window *win, const nl_noise_window *pwin,
               double perlin_freq, const nl_table *t)
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
  nl_harness_verdict_figure(r, "Fig. 2: colour-mapped Perlin and GCTBF patterns",
                            "blue-marble patterns through the 13-knot spline (images only)",
                            "colour.png",
                            "the five combinations are our reading; no number of the paper");
}
