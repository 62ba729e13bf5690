/* C5's settings the thesis does not state, measured on the headline reading
 * (floor.c): the covariance floor of EM and the linkage of the clustering.
 *
 * COVARIANCE FLOOR. EM adds reg_covar to every variance (nl_gmm.h, default
 * 1e-6). The headline fits 1000 rows in d = 2 n_low (cos, sin) dimensions
 * with K0 about 30: a component holds about 1000 / K rows, fewer than d, so
 * its sample covariance has at most n_k - 1 non-zero eigenvalues and the
 * other d - n_k + 1 directions have variance reg_covar. Each row then gains
 * -1/2 ln(reg_covar) of log-likelihood per such direction, and AIC moves by
 * ln 10 sum_k n_k max(0, d - n_k + 1) per decade of the floor (the
 * prediction, column aic_slope_pred) while K stays. floor.tsv: the headline
 * reading refitted at each floor of C5_FLOORS (same rows, seeds and K0),
 * mean and sd over the pool replicates; floor_dims is the mean number of
 * such directions per row of the final model (n_k = n w_k);
 * log10_floor_paper = log10 reg_covar + (paper_AIC - AIC) / aic_slope_pred,
 * the floor at which that law would give the thesis's AIC.
 *
 * LINKAGE. The thesis stops merging "when the Hausdorff distance between the
 * two clusters exceeds the cutoff". For any two point sets, single linkage
 * (nearest pair) <= Hausdorff distance <= complete linkage (farthest pair);
 * the Hausdorff distance itself is not a reducible linkage. linkage.tsv: K0
 * at the thesis's cutoff on the headline's clustered rows (raw angles) under
 * single, average and complete linkage, mean and sd over the replicates:
 * readings, not verdicts. */
#ifndef C5_FLOOR_H
#define C5_FLOOR_H

#include "study/nl_study_cheng.h"

#define C5_NFLOOR 6 /* reg_covar 1e-8 ... 1e-3, one per decade */

typedef struct {
  nl_table *floor, *linkage;
} c5_floor;

void c5_floor_alloc(c5_floor *F);
void c5_floor_free(c5_floor *F);
/* One texture (paper_aic: its thesis AIC), in two steps for shards: the
 * headline options o (its cutoff, distance and sample) refitted at every
 * floor and clustered under every linkage on one replicate's pool (fitted
 * from seed) into out[C5_FLOOR_VALS]; then the rows from every replicate's
 * values (vals[k], k < reps), added to F. Exit 1 on error. */
#define C5_FLOOR_VALS (C5_NFLOOR * 7 + 3)
void c5_floor_unit(nl_harness *r, const char *texture, const nl_cheng_model_options *o,
                   nl_cheng_pool *pool, unsigned long seed, int threads, double *out);
void c5_floor_gather(nl_harness *r, c5_floor *F, const char *texture, double paper_aic,
                     double cutoff, const double *const *vals, int reps);
/* Writes floor.tsv and linkage.tsv. */
void c5_floor_write(nl_harness *r, const c5_floor *F);
/* Their tables and prose in the report. */
void c5_floor_report(nl_harness *r, const c5_floor *F);

#endif
