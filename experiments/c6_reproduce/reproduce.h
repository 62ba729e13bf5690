/* C6's tables (reproduce.c): reps (one row per reproduction: texture, swap,
 * rep, E_ks, p_ks, E_con, ks2_D against the original's angles,
 * ms_reproduce, ms_texture) and its summary (per texture: the original, then
 * the reproductions with and without the swap: means, sd, fractions below
 * the original, times, K). */
#ifndef C6_REPRODUCE_H
#define C6_REPRODUCE_H

#include "controls.h"
#include "study/nl_study_cheng.h"

#define C6_NSHOW        8   /* reproductions shown (montage, CDF) */
#define C6_TEXTURE_SIDE 256 /* the texture timed with a reproduction (ms_texture) */

nl_table *c6_reps_alloc(void);
nl_table *c6_reps_summary_alloc(void);

/* Textures ths[0..n-1], rows in texture order: their originals as one
 * nl_parallel_for on the run's threads, then per texture its pool (threaded
 * inside), the matched-K0 mixture, nrep reproductions with the high entries
 * swapped (fraction `swap`) and nrep without; writes textures_TEX.png (the
 * original and C6_NSHOW reproductions) and cdf_TEX.tsv. The draws stay in order on
 * one thread and the evaluations run on the run's threads, so the tables do
 * not depend on the thread count. A degenerate model is reported in the
 * text, with no reproductions. The controls and other claims' rows go to
 * ctl (controls.h). */
void c6_reproduce_cases(const nl_study_cheng *s, nl_table *reps, nl_table *sum,
                        const nl_study_cheng_thesis_gmm *ths, int n,
                        const nl_cheng_pool_options *po, const nl_cheng_model_options *mo, int nrep,
                        double swap, c6_controls *ctl);

#endif
