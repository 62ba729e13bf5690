/* arcsine.c - S4: the ramp coordinate's CDF against the arcsine law. */
#include "arcsine.h"

#include <math.h>

double s4_arcsine_cdf(double u)
{
  return 2.0 / 3.14159265358979323846 * asin(sqrt(u < 0 ? 0 : u > 1 ? 1 : u));
}

double s4_arcsine_gap(const double *density, int nbins)
{
  double cdf = 0, gap = 0;
  for (int b = 0; b < nbins; b++) {
    cdf += density[b] / nbins;
    gap = fmax(gap, fabs(cdf - s4_arcsine_cdf((b + 1.0) / nbins)));
  }
  return gap;
}

double s4_uniform_gap(int nbins)
{
  double gap = 0;
  for (int b = 0; b < nbins; b++) {
    double u = (b + 1.0) / nbins;
    gap = fmax(gap, fabs(u - s4_arcsine_cdf(u)));
  }
  return gap;
}
