/* c1.h - C1's cost table (cost.c) and report prose (report.c).
 *
 * Cheng 2009 sec. 4.1 (Fig 4.1-4.4) shows cloud, marble, erosion and fire
 * textures, each from three control patterns with its own control term
 * (eq. 3.8, 4.1, 4.2, 4.3). C1 runs each (texture, pattern) with our
 * rescaled formulas and with the thesis's taken literally.
 */
#ifndef C1_H
#define C1_H

#include "study/nl_study_cheng.h"

/* The cost of the optimisations behind a summary, filled by
 * nl_study_cheng_rows_add when set as nl_study_cheng.cost: case (the row's
 * labels joined by "/"), seeds, moves (mean per optimisation), cpu_s (mean
 * thread CPU seconds per full multi-level optimisation, set-up included),
 * cpu_s_sd, moves_per_s (moves over CPU seconds, summed over seeds). */
nl_table *c1_cost_alloc(void);
/* Writes timing.tsv (its times marked "ignore": never regression-checked),
 * its table and a sentence formatted from it into the report. */
void c1_cost_report(nl_harness *r, const nl_table *t);

/* Texture t's figure (Fig 4.(t+1)): its caption, control term `con` by
 * equation `equation`, image `file`. */
void c1_figure_text(nl_harness *r, int t, nl_cheng_con con, const char *equation,
                    const char *file);
/* The thesis's claim, our setting (c), the summary table, controllability,
 * marble's gain and uniformity. */
void c1_text(nl_harness *r, const nl_table *sum, const nl_cheng_config *c, int grid);

#endif
