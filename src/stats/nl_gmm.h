/* nl_gmm.h - Gaussian mixture models fitted by EM, with AIC/BIC selection.
 *
 *   nl_gmm_options o;
 *   nl_gmm_options_default(&o);              // full covariance, tol 1e-3, reg 1e-6, 100 iterations
 *   nl_gmm *g = nl_gmm_alloc(k, d, o.covariance);
 *   if (nl_gmm_fit(g, x, n, &o, &err)) ...   // x: n rows of d, row-major
 *   printf("%g %g %g\n", g->loglik, g->aic, g->bic);
 *   nl_gmm_free(g);
 *
 * The model: p(x) = sum_k w_k N(x; mu_k, Sigma_k), Sigma_k full, diagonal, tied
 * (one for all k) or spherical (sigma_k^2 I), as sklearn's covariance_type.
 * EM is scikit-learn 1.2's GaussianMixture step for step, so from the same
 * initial responsibilities both produce the same iterates to rounding:
 *   - initialisation: responsibilities one-hot from labels (given in
 *     o.init_labels, or from k-means: k-means++ seeding (Arthur &
 *     Vassilvitskii 2007) from o.seed, then Lloyd iterations), then one
 *     M-step; initial weights N_k / n as in sklearn's _initialize;
 *   - E-step: log w_k + log N(x_i; mu_k, Sigma_k) with the Cholesky factor
 *     Sigma_k = L_k L_k^T (gsl_linalg_cholesky_decomp1): the Mahalanobis
 *     term is |L_k^{-1}(x_i - mu_k)|^2, done for blocks of 1024 points by
 *     one triangular multiplication with the inverted factor (gsl_blas_dtrmm,
 *     level-3 BLAS; sklearn's precisions_cholesky_ is its transpose);
 *     responsibilities by log-sum-exp, so no component underflows to 0/0;
 *   - M-step: N_k = sum_i r_ik + 10 eps, mu_k = R^T X / N_k (dgemm),
 *     Sigma_k = sum_i r_ik (x_i - mu_k)(x_i - mu_k)^T / N_k + reg_covar I
 *     (dsyrk on blocks of sqrt(r_ik)(x_i - mu_k)), w_k = N_k / sum N_k.
 *     Rows with r_ik < 1e-20 max_i r_ik are left out of Sigma_k: they lie
 *     so far out that they change it by < 1e-13 relative, and on clustered
 *     data they are most rows (nl_gmm.c, SKIP);
 *   - threads (o.threads, nl_parallel_for): the E-step's (block of 1024
 *     rows, component) pairs and the M-step's components run on threads,
 *     each writing only its own slots; the sums over rows and components
 *     are taken afterwards in order, so every thread count gives the same
 *     bytes;
 *   - stop when the mean log-likelihood (computed in the E-step, i.e. for
 *     the parameters before the M-step, like sklearn's lower_bound) changes
 *     by less than tol, or after max_iter iterations (converged = 0).
 * Results: weights, means, covariances, their Cholesky factors, and for the
 * final parameters loglik = sum_i log p(x_i) (sklearn: score(X) * n),
 * AIC = -2 loglik + 2m, BIC = -2 loglik + m ln n, with m free parameters:
 * full K d(d+1)/2 + K d + K - 1, diagonal 2 K d + K - 1, tied d(d+1)/2 + K d + K - 1,
 * spherical 2K + K d - 1 (sklearn's count).
 * Agreement with sklearn from the same labels: loglik to 1e-8 relative,
 * same iteration count (tests/data/stats/gmm_fit.tsv).
 *
 * reg_covar (default 1e-6) is added to every variance: a constant column
 * then has variance reg_covar instead of 0, and the fit stays finite. A
 * covariance that is still not positive definite gives NL_ENUM.
 *
 * Model selection (Cheng, sec. 3.5.3): nl_gmm_select_aic fits K0, K0+1, ...
 * and stops at the first K whose AIC is not at least `threshold` below the
 * AIC of K-1; it returns the K-1 model (the last one that improved AIC by
 * threshold or more) and the AIC/BIC path of every K it fitted.
 */
#ifndef NL_GMM_H
#define NL_GMM_H

#include "base/nl_base.h"

#include <gsl/gsl_rng.h>

#ifdef __cplusplus
extern "C" {
#endif

/* scikit-learn's covariance_type: full (one matrix per component), diag
 * (variances per component), tied (one matrix shared by all components:
 * the pooled scatter / n + reg_covar I) and spherical (one variance per
 * component: the mean of its diagonal variances). */
typedef enum { NL_GMM_FULL, NL_GMM_DIAG, NL_GMM_TIED, NL_GMM_SPHERICAL } nl_gmm_covariance;
/* "full", "diag", "tied", "spherical"; NL_EINVAL otherwise. */
nl_status nl_gmm_covariance_parse(const char *name, nl_gmm_covariance *c, nl_error *err);
const char *nl_gmm_covariance_name(nl_gmm_covariance c);

typedef struct {
  nl_gmm_covariance covariance;
  double tol;               /* on the mean log-likelihood; 1e-3 */
  double reg_covar;         /* added to variances; 1e-6 */
  size_t max_iter;          /* 100 */
  unsigned long seed;       /* k-means++ seeding; 0 */
  const int *init_labels;   /* n labels in 0..k-1, or NULL for k-means */
  int threads;              /* E- and M-step work on this many threads
                               (nl_parallel_for); 1. Results do not depend on it. */
  struct nl_gmm_memo *memo; /* fits shared between AIC paths (below); NULL */
  struct nl_gmm_workspace *workspace;   /* arrays kept between fits (below); NULL */
} nl_gmm_options;

/* A workspace keeps the large arrays (K d^2 covariances, factors,
 * inverses) of the models an AIC path makes after they are freed, for the
 * next path's models, instead of returning them to the system: a program
 * that fits many paths of large models (C5: about a hundred) spends a
 * third of its time faulting in and zeroing fresh pages without one. At
 * most 32 arrays, 1 GiB; several threads may share one (a mutex). Models
 * made with o.workspace set must be freed before the workspace. Results
 * do not depend on it.
 *   nl_gmm_workspace *w = nl_gmm_workspace_alloc();
 *   o.workspace = w;
 *   ... nl_gmm_select_aic(..., &o, ...) for every path, nl_gmm_free(best) ...
 *   nl_gmm_workspace_free(w);
 * nl_gmm_workspace_alloc returns NULL when out of memory; _bytes is what it
 * holds now. */
typedef struct nl_gmm_workspace nl_gmm_workspace;
nl_gmm_workspace *nl_gmm_workspace_alloc(void);
void nl_gmm_workspace_free(nl_gmm_workspace *w);
size_t nl_gmm_workspace_bytes(const nl_gmm_workspace *w);

void nl_gmm_options_default(nl_gmm_options *o);
/* What nl_gmm_fit (and so nl_gmm_select_aic) accepts, as `stat gmm` parses
 * it: tol and reg_covar in [0, NL_GMM_MAX_TOL] (so finite), max_iter in
 * 1..NL_GMM_MAX_ITER; NL_EINVAL naming the option ("--tol: inf is outside
 * [0, 1e+300]"). */
#define NL_GMM_MAX_TOL 1e300
#define NL_GMM_MAX_ITER 100000000
nl_status nl_gmm_options_check(const nl_gmm_options *o, nl_error *err);

typedef struct {
  size_t k, d;
  nl_gmm_covariance covariance;
  double *weights;     /* k */
  double *means;       /* k x d */
  double *covs;        /* full, tied: k x d x d (tied: k equal copies);
                          diag, spherical: k x d variances (spherical: d equal) */
  double *chol;        /* full, tied: lower L_k (k x d x d, upper part zero);
                          diag, spherical: k x d standard deviations */
  double *prec;        /* full, tied: L_k^{-1} (lower, k x d x d), so that the
                          precision is prec^T prec; diag, spherical: NULL */
  size_t n;            /* rows of the last fit */
  double loglik;       /* sum of log p(x_i) at the final parameters */
  double aic, bic;
  size_t nparams;      /* m */
  size_t iterations;
  int converged;
} nl_gmm;

nl_gmm *nl_gmm_alloc(size_t k, size_t d, nl_gmm_covariance covariance);
/* nl_gmm_alloc with its large arrays taken from (and, at nl_gmm_free,
 * given back to) w; w NULL: nl_gmm_alloc. */
nl_gmm *nl_gmm_alloc_workspace(size_t k, size_t d, nl_gmm_covariance covariance,
                               nl_gmm_workspace *w);
/* Bytes a fit of k components to n rows of d columns needs (responsibilities,
 * k-means distances, two models), and a check of it against the memory
 * available: "200000 rows of 3 columns with 5000 components need 16 GB;
 * 8 GB is available". nl_gmm_fit and nl_gmm_select_aic check first;
 * callers check before nl_gmm_alloc when k and d come from input. */
double nl_gmm_bytes(size_t n, size_t d, size_t k, nl_gmm_covariance covariance);
nl_status nl_gmm_check_size(size_t n, size_t d, size_t k, nl_gmm_covariance covariance,
                            nl_error *err);
void nl_gmm_free(nl_gmm *g);
size_t nl_gmm_nparams(size_t k, size_t d, nl_gmm_covariance covariance);

/* Fits g (its k, d, covariance; o->covariance must match) to n rows.
 * NL_EINVAL: n < 2, k > n, non-finite data, bad options or labels;
 * NL_ENUM: a covariance is not positive definite even with reg_covar. */
nl_status nl_gmm_fit(nl_gmm *g, const double *x, size_t n, const nl_gmm_options *o,
                     nl_error *err);

/* sum_i log p(x_i) under g; logp (may be NULL) receives each log p(x_i). */
nl_status nl_gmm_loglik(const nl_gmm *g, const double *x, size_t n, double *total,
                        double *logp, nl_error *err);

/* sklearn's predict: labels[i] (0..k-1) is the component of largest
 * w_k N(x_i; mu_k, Sigma_k), the first of equal ones. */
nl_status nl_gmm_predict(const nl_gmm *g, const double *x, size_t n, int *labels, nl_error *err);

/* n draws from the mixture into out (n x d); labels (may be NULL) gets the
 * component of each draw. */
void nl_gmm_sample(const nl_gmm *g, gsl_rng *rng, size_t n, double *out, int *labels);

typedef struct {
  size_t k;
  double loglik, aic, bic;
  size_t iterations;
  int converged;
} nl_gmm_step;

/* Fits k0, k0+1, ..., at most k_max (and at most n) components; path
 * (k_max - k0 + 1 entries) receives each fit, *npath how many. *best gets the
 * selected model (caller frees). */
nl_status nl_gmm_select_aic(const double *x, size_t n, size_t d, size_t k0, double threshold,
                            size_t k_max, const nl_gmm_options *o, nl_gmm **best,
                            nl_gmm_step *path, size_t *npath, nl_error *err);

/* A memo of fits for nl_gmm_select_aic (o->memo): several AIC paths on the
 * same rows (C5's readings: K0 from different cutoffs, paths K 28-40 and
 * 30-42) fit the same K again. A fit is a function of the rows (compared
 * byte for byte with a copy the memo keeps), n, d, K, o->seed, covariance,
 * tol, reg_covar and max_iter: EM is deterministic and its values do not
 * depend on the threads, so a remembered fit is the fit. The memo keeps
 * every fit's path entry (nl_gmm_step) and copies of the models paths
 * returned (a few, the oldest dropped beyond a byte budget); a path that
 * selects a K whose model is not kept fits it again. So a path gives the
 * same bytes with or without a memo, only sooner. Thread-safe (a mutex):
 * paths on several threads may share one memo. */
typedef struct nl_gmm_memo nl_gmm_memo;
nl_gmm_memo *nl_gmm_memo_alloc(void);
void nl_gmm_memo_free(nl_gmm_memo *m);
/* Fits done and fits taken from the memo (path entries), for reports. */
void nl_gmm_memo_counts(const nl_gmm_memo *m, size_t *fitted, size_t *reused);

#ifdef __cplusplus
}
#endif

#endif
