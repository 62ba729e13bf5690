/* report.h - A4's report prose (report.c): every number in it is formatted
 * from the run's table and parameters.
 *
 *   a4_run run = {rate2d, length, 64.0, mean_f_sup, seeds, aliasing};
 *   a4_report(r, &run);
 */
#ifndef A4_REPORT_H
#define A4_REPORT_H

#include "harness/nl_harness.h"

/* What the report reads of one run of A4. */
typedef struct {
  double rate;      /* samples per unit of the images (the paper's 2) */
  double length;    /* units of the line F_sup is measured on */
  double fine_rate; /* samples per unit of that line */
  double f_sup;     /* mean F_sup over the seeds */
  int seeds;
  const nl_table *aliasing;
  double extent;     /* side in units of the 2D planes of the energy */
  double plane_rate; /* their samples per unit */
  double paper_f_sup; /* Table 5.2's F_sup: the divisor of panel (b) and the headline */
} a4_run;

/* The paper and our reading, the aliasing table, Fig. 5.7 and its price. */
void a4_report(nl_harness *r, const a4_run *run);
/* The energy above Nyquist against T on the line (aliased_energy.tsv) and
 * on the 2D plane (aliased_energy_2d.tsv), its prose, the verdicts of
 * Fig. 5.7 decided by it, each with its control, and the figure's row. */
void a4_report_energy(nl_harness *r, const a4_run *run, const nl_table *et, const nl_table *et2,
                      double nyquist);
/* The title of Fig. 5.7's montage at the run's rate, into buf. */
void a4_figure_title(const a4_run *run, char *buf, size_t size);

#endif
