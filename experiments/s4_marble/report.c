/* report.c - S4's report prose: Shaffer's marble slides and what the
 * turbulence does to the distribution of the ramp coordinate u. */
#include "s4.h"

#include <math.h>

void s4_report(nl_harness *r, double stripes, int octaves, const nl_noise_window *win,
               const nl_table *dist, const nl_table *bend, int nbins, double uniform_gap)
{
  nl_harness_text(
      r,
      "**Slides:** u = (1 + sin(y)) / 2 through a marble colour ramp, after p.y = p.y "
      "+ a fractal_sum(p) (images only, a not given). **Ours:** %g stripe%s per unit "
      "(u = (1 + sin(2 pi %g (y + a F(p)))) / 2), F the %d-octave fractal sum of "
      "Perlin's improved noise on z = %g (a third of a cell off the lattice planes at every "
      "octave), over [0, %g)^2; a = 0 is the unperturbed "
      "ramp of the slide's first panel. A white-grey-blue ramp of 5 knots.\n",
      stripes, stripes == 1 ? "" : "s", stripes, octaves, win->z, win->size);
  nl_harness_figure(r, "panels.png", "Marble for growing turbulence amplitude a");
  nl_harness_report_table(r, dist, "Mean and sd of u over seeds", 4);
  nl_harness_figure(r, "density.png",
                    "Density of u (mean over seeds) against the arcsine law of pure stripes");
  /* the largest distance over the perturbed amplitudes (a > 0) */
  double gap = 0;
  for (size_t i = 0; i < dist->nrows; i++)
    if (nl_table_value(dist, i, "a") > 0) gap = fmax(gap, nl_table_value(dist, i, "cdf_gap"));
  nl_harness_text(r,
                  "Pure stripes give u the arcsine density 1 / (pi sqrt(u (1 - u))), piling up at "
                  "0 and 1. The fractal displacement changes where the stripes run more than how u "
                  "is distributed: for every a > 0 the CDF of u stays within %.3f of the arcsine "
                  "law at the %d bin edges of the density (cdf_gap), where a uniform u would be "
                  "%.3f away. The unperturbed stripes (a = 0) read %.3f: the pixel grid samples "
                  "their phase at a few fixed values, a floor of this statistic that the noise "
                  "dithers away, so gaps below it are not resolved. The slides claim nothing of "
                  "u's law, so cdf_gap decides no verdict: it is our observation.\n",
                  gap, nbins, uniform_gap, nl_table_value(dist, 0, "cdf_gap"));
  nl_harness_text(r,
                  "**Bend.** The slides' \"we need to add some noise first\" as a number: the "
                  "share of u's squared neighbour differences along x (along the stripes), "
                  "gx_share, is 0 for the straight stripes and %.3f, %.3f, %.3f at a = %g, %g, %g "
                  "(bend.tsv; 1/2 for an isotropic field). The verdict compares a = 0 with the "
                  "smallest a; its control displaces each row by the sum at the row's first "
                  "pixel, moving the stripes by the same noise without bending them: %.3f.\n",
                  nl_table_value(bend, 1, "gx_share"), nl_table_value(bend, 2, "gx_share"),
                  nl_table_value(bend, 3, "gx_share"), nl_table_value(bend, 1, "a"),
                  nl_table_value(bend, 2, "a"), nl_table_value(bend, 3, "a"),
                  nl_table_value(bend, 4, "gx_share"));
}
