/* fit.h - does the thesis's mixture describe its pool? (Cheng 2009 sec. 4.4:
 * "the GMMs we apply is suitable for our input data and fit well").
 *
 * The mixture (nl_cheng_model) is fitted on its input rows; the check uses
 * the pool rows it did not see (held out). Per low angle j, a two-sample KS
 * test between n mixture draws (decoded to angles) and n held-out rows
 * evenly spaced through them, both measured from mu_j - pi (the cut in the
 * widest empty arc, as nl_cheng_model_assess); the mixture fits when no
 * angle's marginal is rejected: p = min(1, nlow x smallest p) (Bonferroni,
 * valid under any dependence between the angles). The negative control
 * runs the same test with uniform angles in place of the draws (a "model"
 * that knows nothing of the pool), which a test with any power rejects.
 *
 *   c5_fit f;
 *   c5_fit_check(pool, m, 1000, rng, &f, &err);
 */
#ifndef C5_FIT_H
#define C5_FIT_H

#include "cheng/nl_cheng_repro.h"

#include <gsl/gsl_rng.h>

typedef struct {
  double p_bonf, ks_median, ks_reject; /* the mixture's draws */
  double p_bonf_uniform, ks_median_uniform, ks_reject_uniform; /* uniform angles */
  size_t n_held, n_compared;
} c5_fit;

/* NL_EINVAL without a mixture or without held-out rows. */
nl_status c5_fit_check(const nl_cheng_pool *pool, const nl_cheng_model *m, size_t n_draw,
                       gsl_rng *rng, c5_fit *out, nl_error *err);
/* Free parameters of one full-covariance component in d dimensions,
 * d (d + 1) / 2 + d + 1 (a mean, a covariance and a weight): one more
 * component raises AIC = -2 L + 2 m (eq. 3.19) by twice this unless the
 * log-likelihood L rises by as much. */
double c5_params_per_component(double d);

#endif
