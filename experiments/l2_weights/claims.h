/* claims.h - L2's verdict rows (claims.c): the paper's two statements about
 * Fig. 4, "the two sets of weights are very similar" and "the power
 * converges to the expected power with increasing sample size", decided by
 * eq. 12's weight error over seeds. */
#ifndef L2_CLAIMS_H
#define L2_CLAIMS_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* "Very similar", read before the run: the relative RMS weight error
 * |w_est - w| / |w| at most a tenth (reproduced) or a quarter (partly) of
 * the weights' size. */
#define L2_SIMILAR_RULE "abs 0.1 0.25"

/* The per-seed trend of an error against image size: err[i * seeds + s] at
 * side sizes[i], i < nsizes. Each seed's least-squares slope of the error
 * on log2(side) (per doubling); *mean and *sd over seeds, and the one-sided
 * p-value of a one-sample t-test that the mean slope is below 0 (the error
 * falls). With fewer than 2 sizes or seeds, p = 1. */
void l2_trend(const double *err, const int *sizes, int nsizes, int seeds, double *mean, double *sd,
              double *p);

/* Writes similar.tsv (quantity, paper, ours, ours_sd, seeds: eq. 12's
 * relative weight error at side `size` over the sweep's seeds, from
 * estimators.tsv et; paper 0; no row when the sweep lacks that side) and
 * trend.tsv (bands, slope_mean, slope_sd, p_falls, seeds, sizes: rows "all"
 * and the `fine` finest bands, from err_all and err_fine, nsizes x seeds at
 * the sides `sizes`, by l2_trend) and declares their verdicts: "very
 * similar" by rule L2_SIMILAR_RULE, "falls with size" by the t-test's p
 * (rule "p 0.01 0.05"); all independent. Returns similar.tsv's table, *trend
 * trend.tsv's (caller frees both). */
nl_table *l2_claims(nl_harness *r, const nl_table *et, int size, const double *err_all,
                    const double *err_fine, const int *sizes, int nsizes, int seeds, int fine,
                    nl_table **trend);

#endif
