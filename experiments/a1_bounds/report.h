/* report.h - A1's report prose (report.c): every number in it is formatted
 * from the run's table and parameters.
 *
 *   a1_run run = {nmax, points, seeds, bounds, max_noise};
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
} a1_run;

/* The paper's bounds and our check, the table, its figure, and how many
 * points left the paper's bounds and the analytic ones. */
void a1_report(nl_harness *r, const a1_run *run);

/* claims.tsv and its verdicts: points over the paper's octave, fractal and
 * incremental bounds (paper 0), and the largest |noise| the climbs found
 * against the paper's 1, with what it means for the bounds. */
void a1_verdicts(nl_harness *r, const a1_run *run);

#endif
