/* s4.h - S4's report prose (report.c). */
#ifndef S4_H
#define S4_H

#include "harness/nl_harness.h"
#include "noise/nl_noise.h"

/* The slides' marble and ours (stripes per unit, octaves of the fractal
 * sum, the window win), the panels, the table dist (distribution.tsv, with
 * each a's cdf_gap from the arcsine law at the edges of nbins bins) and the
 * density figure; uniform_gap is a uniform u's distance at the same edges;
 * bend the table bend.tsv (rows a = 0, then the a > 0 of the sweep, then
 * the rows-only control). */
void s4_report(nl_harness *r, double stripes, int octaves, const nl_noise_window *win,
               const nl_table *dist, const nl_table *bend, int nbins, double uniform_gap);

#endif
