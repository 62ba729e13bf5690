/* report.h - A2's report prose (report.c): every number in it is formatted
 * from the run's tables and parameters, the paper's Table 5.1 from
 * a2_run.paper_ms.
 *
 *   a2_report_fit(r, &run);      // the paper, the fit, this run, the tables
 *   a2_verdicts(r, &run);        // Table 5.1's ratios (fitted) and their growth
 *   a2_report_images(r, &run);   // the images' agreement and the figures
 */
#ifndef A2_REPORT_H
#define A2_REPORT_H

#include "joint.h"

/* What the report reads of one run of A2. */
typedef struct {
  const a2_smoke_scene *sc;   /* the scene of the parameters (the headline) */
  const a2_smoke_scene *best; /* the sweep's best reading */
  const int *label;           /* the octave counts N of Table 5.1 */
  int n;
  const double (*paper_ms)[2]; /* Table 5.1: plain and bounded ms per row */
  const double *paper;         /* their ratios */
  const double *check_slope;   /* the size check's slopes; [0] is the alternative */
  int seeds, sweep_seeds, sweep_size;
  const a2_smoke_vary *vary;
  int nvary;
  const a2_smoke_point *pt; /* the headline curve */
  const nl_table *timing, *fit, *sweep, *size_check;
  const nl_table *joint, *growth; /* joint_fit.tsv, growth.tsv */
  const a2_smoke_pair *unit;      /* the paper's unit bound at the largest N */
} a2_run;

/* The paper and the fit, where the paper's ratios appear in the sweep,
 * this run's scene, and the timing and fit tables. */
void a2_report_fit(nl_harness *r, const a2_run *run);
/* The verdicts: the six ratios of Table 5.1 (kind "fitted 3/6": slope,
 * f0 and kappa fitted jointly to them), and their growth from the third
 * row to the last, which the slope does not set (independent), with its
 * prose; and the cost per term. */
void a2_verdicts(nl_harness *r, const a2_run *run);
/* How far the bounded images are from the plain ones (and with the unit
 * bound), and the captions of Fig. 5.2, 5.3 and the timing figure. */
void a2_report_images(nl_harness *r, const a2_run *run);

#endif
