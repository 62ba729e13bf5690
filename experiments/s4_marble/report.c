/* report.c - S4's report prose: Shaffer's marble slides and what the
 * turbulence does to the distribution of the ramp coordinate u. */
#include "s4.h"

void s4_report(nl_harness *r, double stripes, int octaves, double extent, const nl_table *dist)
{
  nl_harness_text(r,
                  "**Slides:** u = (1 + sin(y)) / 2 through a marble colour ramp, after p.y = p.y "
                  "+ a fractal_sum(p) (images only, a not given). **Ours:** %g stripe%s per unit "
                  "(u = (1 + sin(2 pi %g (y + a F(p)))) / 2), F the %d-octave fractal sum of "
                  "Perlin's improved noise on z = 0.5, over [0, %g)^2; a = 0 is the unperturbed "
                  "ramp of the slide's first panel. A white-grey-blue ramp of 5 knots.\n",
                  stripes, stripes == 1 ? "" : "s", stripes, octaves, extent);
  nl_harness_figure(r, "panels.png", "Marble for growing turbulence amplitude a");
  nl_harness_report_table(r, dist, "Mean and sd of u over seeds", 4);
  nl_harness_figure(r, "density.png",
                    "Density of u (mean over seeds) against the arcsine law of pure stripes");
  nl_harness_text(r,
                  "Pure stripes give u the arcsine density 1 / (pi sqrt(u (1 - u))), piling up at "
                  "0 and 1. The fractal displacement changes where the stripes run, not how u is "
                  "distributed: the density stays close to the arcsine law for every a, which is "
                  "why marble keeps the ramp's end colours dominant however turbulent it gets.\n");
}
