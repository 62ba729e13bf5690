/* C5's tables (pools.c): gmm (Tables 4.2-4.4 per texture, split and cutoff
 * rule, the thesis's numbers beside ours), path (AIC/BIC along K, first
 * seed), curve (K against the cutoff), runs (E_R per pool run), assess
 * (held-out checks of three model variants), fit (the thesis's full
 * mixture against held-out rows, and uniform angles as its control: fit.h),
 * orig (the original table against its pool). */
#ifndef C5_POOLS_H
#define C5_POOLS_H

#include "study/nl_study_cheng.h"

typedef struct {
  nl_table *gmm, *path, *curve, *runs, *assess, *fit, *orig;
} c5_pools;

#define C5_MAXSEEDS     64   /* seeds of the model fits averaged per row */
#define C5_ASSESS_DRAWS 1000 /* mixture draws (and pool rows) per held-out KS check */

void c5_pools_alloc(c5_pools *T);
/* Writes the seven tables (original.tsv, gmm.tsv, aic_path.tsv, cutoff_k.tsv,
 * pool_runs.tsv, assess.tsv, fit.tsv) and marks their timing columns "ignore". */
void c5_pools_write(nl_harness *r, const c5_pools *T);
void c5_pools_free(c5_pools *T);
/* The seven tables' rows into the current unit (nl_harness_unit_put_table),
 * and back: appended to T from unit u. */
void c5_pools_put(nl_harness *r, const c5_pools *T);
void c5_pools_get(nl_harness *r, long u, c5_pools *T);

/* One texture at one low/high split: the original and its pool, a gmm and
 * path row per cutoff rule (the thesis's cutoff; the one matching its K0)
 * over nseeds seeds of the fit, K against the cutoff, and with `full` the
 * held-out checks. */
void c5_pool_case(const nl_study_cheng *s, c5_pools *T, const nl_study_cheng_thesis_gmm *th,
                  const nl_cheng_pool_options *po, const nl_cheng_model_options *mo, int nseeds,
                  int full);
/* The same from an already collected original and pool rp. */
void c5_pool_case_with(const nl_study_cheng *s, c5_pools *T, const nl_study_cheng_thesis_gmm *th,
                       const nl_cheng_pool_options *po, const nl_cheng_model_options *mo,
                       int nseeds, int full, nl_study_cheng_repro *rp);

#endif
