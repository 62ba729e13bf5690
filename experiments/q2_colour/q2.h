/* q2.h - Q2's report prose (report.c). */
#ifndef Q2_H
#define Q2_H

#include "harness/nl_harness.h"
#include "noise/nl_noise.h"

/* Eq. 4 and our reading (the window of the GCTBF panels win, the Perlin
 * panel's pwin and frequency), the table t (values.tsv), the figure and its
 * qualitative verdict row. */
void q2_report(nl_harness *r, const nl_noise_window *win, const nl_noise_window *pwin,
               double perlin_freq, const nl_table *t);

#endif
