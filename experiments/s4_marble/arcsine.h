/* arcsine.h - S4: how far the ramp coordinate u is from the arcsine law of
 * pure stripes (arcsine.c). */
#ifndef S4_ARCSINE_H
#define S4_ARCSINE_H

/* The arcsine law's CDF, A(u) = (2 / pi) asin(sqrt(u)): the law of
 * u = (1 + sin(phase)) / 2 for a phase uniform mod 2 pi. */
double s4_arcsine_cdf(double u);

/* The largest |CDF - A| at the upper edges of nbins equal bins of [0, 1],
 * density[b] the density of u in bin b (samples per bin per unit of u):
 * the Kolmogorov distance seen at the edges. */
double s4_arcsine_gap(const double *density, int nbins);

/* The same distance for a uniform u: the scale of a gap that is not small. */
double s4_uniform_gap(int nbins);

#endif
