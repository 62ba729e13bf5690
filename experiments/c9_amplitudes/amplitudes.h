/* amplitudes.h - C9's octave amplitudes as variables (amplitudes.c). */
#ifndef C9_AMPLITUDES_H
#define C9_AMPLITUDES_H

#include "study/nl_study_cheng.h"

/* C9, octave amplitudes as variables. */

/* One case's k evaluations (nl_study_cheng_runs, config c: fixed or optimised
 * amplitudes, c->amp_vary): the summary row as nl_study_cheng_rows_add; with
 * amp_vary, one row per octave appended to `gains`
 * (nl_study_cheng_gains_alloc: the labels, octave, a_thesis, a, a_sd, gain,
 * gain_sd, log_gain_sd, R = amp_range, at_bound = fraction of seeds whose
 * |ln gain| is within 1e-3 of ln R); one row to `timing` (labels, seconds_per_run). The
 * first seed's log gains into first_log_gain (F values; seconds_per_run: mean thread CPU seconds of one
 * optimisation, nl_cheng_eval.cpu_seconds). */
nl_table *nl_study_cheng_gains_alloc(int nlabels, const char *const *labels);
nl_table *nl_study_cheng_timing_alloc(int nlabels, const char *const *labels);
void nl_study_cheng_amp_rows(const nl_study_cheng *s, const nl_cheng_config *c, const nl_cheng_eval *evs,
                             nl_table *sum, nl_table *gains, nl_table *timing, int nlabels,
                             const char *const *labels, double *first_log_gain);
/* C9's prose, formatted from the summary (fixed and optimised rows in pairs
 * 2i, 2i + 1), the Welch table (quantity rows per case) and the gains. */
void nl_study_cheng_amp_text(nl_harness *r, const nl_table *sum, const nl_table *tests, const nl_table *gains, double range);

#endif
