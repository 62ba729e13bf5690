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

#define C9_NCOND 3 /* rows per case: fixed, optimised, optimised_wide */

/* The gains table: the nlabels label columns, then octave, a_thesis, a,
 * a_sd, gain, gain_sd, log_gain_sd, R (amp_range), at_bound (fraction of
 * seeds whose |ln gain| is within 1e-3 of ln R). */
nl_table *c9_gains_alloc(int nlabels, const char *const *labels);
/* The timing table: the labels, then seconds_per_run (mean thread CPU
 * seconds of one optimisation, nl_cheng_eval.cpu_seconds). */
nl_table *c9_timing_alloc(int nlabels, const char *const *labels);
/* E_Con's parts table: the labels, then seeds and mean and sd over seeds
 * of E_con, E_con_offset, E_con_contrast and E_con_shape (nl_cheng_eval:
 * n (mean c - mean D)^2, n (sd c - sd D)^2, 2 n sd c sd D (1 - r)),
 * octave1_share(_sd), and one_minus_r(_sd), 1 - r with the pattern: the
 * shape part divided by its scale 2 n sd c sd D, the only part a contrast
 * change leaves alone (the shape part itself grows with sd c). */
nl_table *c9_parts_alloc(int nlabels, const char *const *labels);
/* The tables a case's rows go to, in the same row order. */
typedef struct {
  nl_table *sum, *parts, *gains, *timing;
} c9_tables;
/* One condition's k evaluations (nl_study_cheng_runs under config c, fixed
 * or optimised amplitudes): its summary row (nl_study_cheng_rows_add) and
 * parts row, one row per octave to gains if c->amp_vary, one row to timing,
 * and the first seed's log gains (c->octaves values) into first_log_gain. */
void c9_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
             const c9_tables *t, int nlabels, const char *const *labels, double *first_log_gain);

/* The run's tables t, their controls b (only b's summary and parts are
 * results: baselines.tsv, baselines_parts.tsv) and the Welch tests, in the
 * order of the manifest; timing.tsv's CPU seconds are not checked. */
void c9_tables_write(nl_harness *r, const c9_tables *t, const c9_tables *b, const nl_table *tests);
/* Frees the four tables of t. */
void c9_tables_free(c9_tables *t);

/* The negative control of the verdicts: c's octave gains fixed at random,
 * log g_l uniform in [-ln R, ln R] (R = c->amp_range) from the stream
 * (seed, "c9.random_gains", index), amp_vary 0: the amplitudes change as
 * much as the optimiser may change them, but not towards the pattern. */
void c9_random_gains(nl_cheng_config *c, unsigned long seed, int index);

/* The Welch tests of one case, rows f (fixed), f + 1 (optimised), f + 2
 * (optimised within the wide bounds) of t's tables: optimised vs fixed on
 * the nq summary columns q and on E_Con's three parts, then wide vs
 * optimised on E_con, contrast, r_pattern and E_con_shape. */
void c9_tests_add(nl_table *tests, const c9_tables *t, size_t f, const char *group,
                  const char *const *q, size_t nq);

/* The thesis's proposal, our method and setting (amplitude bounds R and
 * the wide R_wide). */
void c9_intro_text(nl_harness *r, const nl_study_cheng *s, double range, double wide);
/* The summary, parts, Welch and gains tables, then the prose formatted from
 * them: the counts of cases the optimised amplitudes help or hurt, E_Con's
 * parts, the wide bounds, then one line per case. */
void c9_results_text(nl_harness *r, const c9_tables *t, const nl_table *tests, double range);
/* Per case (rows 3i, 3i + 1 of the summary and parts tables), the verdict
 * rows: E_Con and the shape statistic 1 - r lower with optimised amplitudes
 * (Welch), each with its negative control from b (baselines.tsv: rows 2i
 * fixed, 2i + 1 random gains, c9_random_gains). */
void c9_verdicts(nl_harness *r, const c9_tables *t, const c9_tables *b, const nl_table *tests,
                 int ncase);
/* Mean CPU time per optimisation, fixed (timing rows 0, 2, ...) against
 * optimised (1, 3, ...), over ncase cases; then the figures' captions. */
void c9_timing_text(nl_harness *r, const nl_table *timing, int ncase);

#endif
