/* report.h - A3's report prose (report.c): every number in it is formatted
 * from the run's tables and readings, the paper's Table 5.2 from
 * a3_run.paper.
 *
 *   a3_report_tables(r, &run);    // the paper, the headline reading, the readings
 *   a3_verdicts(r, &run);         // Table 5.2's six numbers, headline and selected
 *   a3_report_figures(r, &run);   // the figures, the sweep and what it shows
 */
#ifndef A3_REPORT_H
#define A3_REPORT_H

#include "harness/nl_harness.h"
#include "tables.h"

/* What the report reads of one run of A3. */
typedef struct {
  const double (*paper)[2];     /* Table 5.2: {F_inf, F_sup} per signal */
  const a3_reading *base, *sel; /* the headline (base) reading and the selected one */
  const char *const *name;      /* the readings' names, a3_readings order */
  int nh, win, close;           /* readings; the selected; the closest in F_sup */
  const int *nin;               /* per reading, how many of the paper's bounds are within */
  const double (*worst)[2];     /* per reading, the largest |z_sup| and |z_inf| */
  int seeds, sweep_seeds;
  const double (*m)[7], (*ms)[7]; /* a3_bandwidth_seeds of the headline, the selected */
  const nl_table *bandwidth, *selected, *hypotheses, *psd; /* selected: bandwidth_selected.tsv */
  const nl_table *sweep, *sweep_sel; /* sweep_sel NULL when the selected is the base */
  const nl_table *control;           /* control_shuffled.tsv: the headline's samples shuffled */
  const nl_table *ratio;             /* sum_over_octave.tsv: F_sup of Fnoise_2 / 2nd octave's */
} a3_run;

/* The paper and the reading of the bandwidth table, the table, the
 * readings' summary and the hypotheses table. */
void a3_report_tables(nl_harness *r, const a3_run *run);
/* The verdicts (verdicts.c): F_inf and F_sup of each signal under the
 * headline reading, kind "independent"; under the selected reading, kind
 * "selected 1/N" (N readings), except an F_inf that sigma = RMS puts on the
 * first bin where the paper's value is that bin: "by construction". */
void a3_verdicts(nl_harness *r, const a3_run *run);
/* The figures, the sensitivity table and what the sweep and the readings
 * say about the paper's F_sup and F_inf. */
void a3_report_figures(nl_harness *r, const a3_run *run);

#endif
