/* q3.h - Q3's report prose (report.c). */
#ifndef Q3_H
#define Q3_H

#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"

/* Eq. 6 and our reading of it (the square [0, extent)^2, scale k,
 * displacement amp, the light direction), the table t (bumps.tsv) and the
 * figure of the original plane and octaves 0..max_oct. */
void q3_report(nl_harness *r, double extent, double k, double amp, const double light[3],
               int max_oct, const nl_table *t, const nl_table *cen);

/* The spectral centroid of a w x w height field over a square of side
 * extent: sum f P(f) / sum P(f) over the radially averaged power of the
 * field less its mean (nl_spectrum_radial), in cycles per unit. Finer
 * wrinkles move it up. */
double q3_centroid(const double *h, int w, double extent);

/* Eq. 6's bump without its frequency doubling, the negative control of the
 * centroid: every octave i at scale k (not 2^i k), fractal = sum_{i<=oct}
 * |0.5 - GCTBF(k x)| / 2^i, bump = fractal^3, on win into out. */
void q3_bump_one_scale(const nl_cellular_gctbf_basis *b, int octaves, double k,
                       const nl_noise_window *win, double *out);

#endif
