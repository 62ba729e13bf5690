/* report.h - A1's report prose (report.c): every number in it is formatted
 * from the run's table and parameters.
 *
 *   a1_run run = {nmax, points, seeds, bounds, max_noise, fractal, printed};
 *   a1_report(r, &run);
 *   a1_verdicts(r, &run);
 */
#ifndef A1_REPORT_H
#define A1_REPORT_H

#include "harness/nl_harness.h"

/* What the report reads of one run of A1. */
typedef struct {
  int nmax;    /* octave counts 1..nmax */
  long points; /* random points per octave count and seed */
  int seeds;
  const nl_table *bounds;    /* bounds.tsv */
  const nl_table *max_noise; /* max_noise.tsv: the climbs of |noise|, one row per seed */
  const nl_table *fractal;   /* fractal_climbs.tsv: climbs of |Fnoise_n| / S_{n-1} */
  const nl_table *printed;   /* printed.tsv: eq. 5.4 as printed, per seed */
} a1_run;

/* The paper's bounds and our check, the table, its figure, and how many
 * points left the paper's bounds and the analytic ones. */
void a1_report(nl_harness *r, const a1_run *run);

/* claims.tsv and its verdicts: climbs over the paper's octave and fractal
 * bounds and random points over eq. 5.4 as printed and as an interval
 * (paper 0), each beside its control (random points, a remainder bound of
 * 0), and what the largest |noise| found means for the bounds. */
void a1_verdicts(nl_harness *r, const a1_run *run);

#endif
