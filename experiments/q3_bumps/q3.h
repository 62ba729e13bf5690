/* q3.h - Q3's report prose (report.c). */
#ifndef Q3_H
#define Q3_H

#include "harness/nl_harness.h"

/* Eq. 6 and our reading of it (the square [0, extent)^2, scale k,
 * displacement amp, the light direction), the table t (bumps.tsv) and the
 * figure of the original plane and octaves 0..max_oct. */
void q3_report(nl_harness *r, double extent, double k, double amp, const double light[3],
               int max_oct, const nl_table *t);

#endif
