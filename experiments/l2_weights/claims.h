/* claims.h - L2's verdict rows (claims.c): the paper's two statements about
 * Fig. 4, "the two sets of weights are very similar" and "the power
 * converges to the expected power with increasing sample size", decided by
 * eq. 12's weight error over seeds. */
#ifndef L2_CLAIMS_H
#define L2_CLAIMS_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* "Very similar", read before the run: the relative RMS weight error
 * |w_est - w| / |w| within a tenth of 0, shown by equivalence
 * (docs/experiments.md). */
#define L2_SIMILAR_RULE "equiv abs 0.1 0.05 0.2"
/* The paper's explanation, sampling error of the band powers: a band of
 * fixed frequency holds 4x the Fourier coefficients per doubling of the
 * side, so its power's relative error, and the weight's, halves: slope -1
 * of log2 error on log2 side, margin 0.2 (docs/experiments.md). */
#define L2_HALVING_RULE "equiv abs 0.2 0.05 0.2"

/* The control of L2's rows: weights drawn at random from the range the
 * true weights are drawn from (nl_byexample_trial), for the trial of seed
 * seeds[i] at side sizes[j]: err[j * n + i] = |w' - w| / |w| over all the
 * side's bands, fine[...] over the nfine finest. */
void l2_random_errors(const unsigned long *seeds, int n, const int *sizes, int nsizes, int nfine,
                      double *err, double *fine);

/* The per-seed trend of an error against image size: err[i * seeds + s] at
 * side sizes[i], i < nsizes. Each seed's least-squares slope of the error
 * on log2(side) (per doubling); *mean and *sd over seeds, and the one-sided
 * p-value of a one-sample t-test that the mean slope is below 0 (the error
 * falls). With fewer than 2 sizes or seeds, p = 1. */
void l2_trend(const double *err, const int *sizes, int nsizes, int seeds, double *mean, double *sd,
              double *p);

/* Writes similar.tsv (quantity, paper, ours, ours_sd, ours_se, seeds:
 * eq. 12's relative weight error at side `size` over the sweep's seeds,
 * from err_all, then the same for random weights; paper 0) and trend.tsv
 * (bands, slope_mean, slope_sd, p_falls, log_slope_mean, log_slope_sd,
 * log_slope_se, paper_log_slope, seeds, sizes: rows "all" and the `fine`
 * finest bands, from err_all and err_fine, nsizes x seeds at the sides
 * `sizes`, by l2_trend on the error and on its log2; then the same rows for
 * random weights) and declares their verdicts, each with the random
 * weights as its control: "very similar" by L2_SIMILAR_RULE, "falls with
 * size" by the t-test's p (rule "p 0.01 0.05"), "halves per doubling" by
 * L2_HALVING_RULE; all independent. seed0: the sweep's (its trials' seeds,
 * stream "l2.size_trial"). Returns similar.tsv's table, *trend trend.tsv's
 * (caller frees both). */
nl_table *l2_claims(nl_harness *r, int size, const double *err_all, const double *err_fine,
                    const int *sizes, int nsizes, int seeds, int fine, unsigned long seed0,
                    nl_table **trend);

#endif
