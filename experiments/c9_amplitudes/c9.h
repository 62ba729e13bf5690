/* c9.h - C9's octave amplitudes as variables: the rows of a case
 * (amplitudes.c) and the report prose (report.c).
 *
 * Cheng 2009 ch. 5 proposes adjusting the fractal sum's amplitudes 1/a_l
 * (eq. 3.10) to follow the control pattern more closely. C9 runs each case
 * with fixed amplitudes (summary row 2i) and with optimised ones (row 2i + 1,
 * nl_cheng_config.amp_vary: gains g_l in [1/R, R], a_l = a_l^thesis / g_l).
 */
#ifndef C9_H
#define C9_H

#include "study/nl_study_cheng.h"

/* The gains table: the nlabels label columns, then octave, a_thesis, a,
 * a_sd, gain, gain_sd, log_gain_sd, R (amp_range), at_bound (fraction of
 * seeds whose |ln gain| is within 1e-3 of ln R). */
nl_table *c9_gains_alloc(int nlabels, const char *const *labels);
/* The timing table: the labels, then seconds_per_run (mean thread CPU
 * seconds of one optimisation, nl_cheng_eval.cpu_seconds). */
nl_table *c9_timing_alloc(int nlabels, const char *const *labels);
/* One case's k evaluations (nl_study_cheng_runs under config c, fixed or
 * optimised amplitudes): its summary row (nl_study_cheng_rows_add), one row
 * per octave to `gains` if c->amp_vary, one row to `timing`, and the first
 * seed's log gains (c->octaves values) into first_log_gain. */
void c9_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
             nl_table *sum, nl_table *gains, nl_table *timing, int nlabels,
             const char *const *labels, double *first_log_gain);

/* The thesis's proposal, our method and setting (amplitude bound R). */
void c9_intro_text(nl_harness *r, const nl_study_cheng *s, double range);
/* The summary, Welch and gains tables, then the prose formatted from them:
 * the counts of cases the optimised amplitudes help or hurt, then one line
 * per case. */
void c9_results_text(nl_harness *r, const nl_table *sum, const nl_table *tests,
                     const nl_table *gains, double range);
/* Mean CPU time per optimisation, fixed (timing rows 0, 2, ...) against
 * optimised (1, 3, ...), over ncase cases; then the figures' captions. */
void c9_timing_text(nl_harness *r, const nl_table *timing, int ncase);

#endif
