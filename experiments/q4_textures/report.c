/* report.c - Q4's report prose: what Qin & Yang 2000 show in Fig. 5 and 6,
 * how we read what they leave open, and what the wood panels measure. */
#include "q4.h"
#include "study/nl_study.h"

static void q4_report_readings(const q4 *q)
{
  const nl_table *wt = q->wood;
  nl_harness_text(
      q->r,
      "**Paper (Fig. 5, 6):** cloud pattern eq. 7 for Perlin and five GCTBF; marble sum (-1)^i F_i "
      "+ sum (-1)^(i+j) F_i F_j, wood F1 - F1F1 and F3 - F3F3, sky F1F2 + F2F3 and F1, flame F1 "
      "(images only; colours other than the sky/cloud of eq. 7 and the marble knots of sec. 4.1 "
      "are not given). **Ours:** plane z = %g (Perlin's: z = %.4g, a third of a cell off the "
      "lattice planes at every octave for k a power of 2, where the octaves' gradients would "
      "line up with the axes), [0, %g)^2 scaled by k = %g, %d octaves after the "
      "first in eq. 7 and the flame, lambda = 4 with inverse-CDF counts, %d seeds for the "
      "numbers.\n\n**Readings:** smoothscale() of eq. 7 (an antialiasing fade tied to the "
      "RenderMan footprint) is 1; Fig. 5's five combinations are drawn, not named: we use F1, F2, "
      "F1 + F1F1, F1 + F1F2, F1F2 + F2F3, whose values lie around 1/2 where 1 - 2 GCTBF changes "
      "sign (combinations with small values such as F1F1 or F2 - F1 make every octave positive and "
      "the sky saturates to cloud); marble maps clamp(GCTBF, 0, 1) through the 13-knot spline of "
      "sec. 4.1; the wood ramp alternative maps [0, 0.25] (the range of F - F^2 for F <= 1) "
      "linearly from light to dark brown; flame maps the fractal sum of F1 over [0.2, 1] through a "
      "black-red-orange-yellow-white spline.\n\n**Wood:** the paper names only the basis inside a "
      "RenderMan wood shader it does not print (it cites Ebert et al., Texturing & Modeling). We "
      "read it as the usual solid wood: rings u = frac(%g r + %g GCTBF) of the distance r to a "
      "tree axis, light to dark wood by the ring profile of the RenderMan Companion's wood (table: "
      "an axis along x tilted into the board; trunk: cut across its axis). The basis moves the "
      "rings by %.2f (table) and %.2f (trunk) rings (sd); across the middle line the shader shows "
      "%.1f and %.1f dark bands (the axis geometry alone %g and %g), the ramp reading %.1f and "
      "%.1f (mean over seeds; table below). Beside real wood (first seed, wood.png): the trunk "
      "shows concentric rings with a sharp dark late-wood edge, but faceted, kinked at the cell "
      "borders of F3; the table shows bands along the axis that wander and close into small rings "
      "around F1's feature points, like knots; neither has the fine fibre grain of wood (the basis "
      "is isotropic, not stretched along the axis). The ramp reading shows cells and creases, no "
      "rings.\n",
      q->win.z, NL_STUDY_SLICE_Z, q->win.size, q->k, q->octaves, q->seeds, q->rings, q->turb,
      nl_table_value(wt, 0, "perturb_rings_sd"), nl_table_value(wt, 1, "perturb_rings_sd"),
      nl_table_value(wt, 0, "rings"), nl_table_value(wt, 1, "rings"),
      nl_table_value(wt, 0, "rings_geometry"), nl_table_value(wt, 1, "rings_geometry"),
      nl_table_value(wt, 0, "ramp_bands"), nl_table_value(wt, 1, "ramp_bands"));
}

void q4_report(const q4 *q)
{
  q4_report_readings(q);
  nl_harness_report_table(q->r, q->t, "Value statistics before colour mapping (mean over seeds)",
                          4);
  nl_harness_figure(q->r, "clouds.png", "Fig. 5: eq. 7 clouds, Perlin and five GCTBF combinations");
  nl_harness_report_table(
      q->r, q->wood,
      "Wood: basis sd, ring displacement (rings, sd), ring-profile sd, dark bands across the "
      "middle line (mean, sd over seeds; without the basis; the ramp reading)",
      3);
  nl_harness_figure(q->r, "textures.png",
                    "Fig. 6: marble, wood (a wood shader on the GCTBF), sky and flame");
  nl_harness_figure(
      q->r, "wood.png",
      "Wood, table (F1 - F1F1) and trunk (F3 - F3F3): the ramp reading beside the wood shader");
  const nl_table *wt = q->wood;
  nl_harness_text(
      q->r,
      "**Whose rings.** The rings of our wood come from the ring shader we added, not from the "
      "GCTBF: the shader without the basis shows %g and %g dark bands (table, trunk), with it "
      "%.1f and %.1f, and the GCTBF alone through the ramp %.1f and %.1f (rings.tsv). The "
      "verdicts \"ramp below wood shader\" have the shader without the GCTBF as their control: "
      "where it passes the same rule, the row counts as by construction, and Fig. 6's wood is no "
      "evidence that the GCTBF makes rings.\n",
      nl_table_value(wt, 0, "rings_geometry"), nl_table_value(wt, 1, "rings_geometry"),
      nl_table_value(wt, 0, "rings"), nl_table_value(wt, 1, "rings"),
      nl_table_value(wt, 0, "ramp_bands"), nl_table_value(wt, 1, "ramp_bands"));
  nl_harness_verdict_figure(q->r, "Fig. 5: eq. 7 clouds, Perlin and five GCTBF",
                            "cellular clouds beside Perlin's (images only)", "clouds.png",
                            "the five combinations are our reading: the figure names none");
  nl_harness_verdict_figure(q->r, "Fig. 6: marble, wood, sky and flame textures",
                            "GCTBF textures (images only)", "textures.png",
                            "colours, wood shader and amplitudes are our reading");
}
