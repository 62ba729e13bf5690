/* s4.h - S4's report prose (report.c). */
#ifndef S4_H
#define S4_H

#include "harness/nl_harness.h"

/* The slides' marble and ours (stripes per unit, octaves of the fractal
 * sum, the square [0, extent)^2), the panels, the table dist
 * (distribution.tsv) and the density figure. */
void s4_report(nl_harness *r, double stripes, int octaves, double extent, const nl_table *dist);

#endif
