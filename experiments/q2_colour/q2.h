/* q2.h - Q2's report prose (report.c). */
#ifndef Q2_H
#define Q2_H

#include "harness/nl_harness.h"

/* Eq. 4 and our reading (the square [0, extent)^2, the Perlin panel's
 * frequency), the table t (values.tsv) and the figure. */
void q2_report(nl_harness *r, double extent, double perlin_freq, const nl_table *t);

#endif
