/* nl_gmm.c - EM for Gaussian mixtures (scikit-learn 1.2's GaussianMixture,
 * sklearn/mixture/_gaussian_mixture.py, on level-3 BLAS): options, the E-
 * and M-steps, a fit, and the fitted model's log-likelihood, labels and
 * samples. Initialisation, models and the AIC path are in nl_gmm_init.c,
 * nl_gmm_workspace.c and nl_gmm_path.c. */
#define _GNU_SOURCE   /* RTLD_DEFAULT */
#include "stats/nl_gmm_internal.h"
#include "stats/nl_stats_gsl.h"
#include "stats/nl_cluster.h"

#include <float.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_randist.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- OpenBLAS threads ----------------------------------------------------- */

/* EM's BLAS calls work on one component's block at a time: at most 1024
 * rows by d columns against a d x d factor. Below 2^26 multiply-adds per
 * call OpenBLAS's second thread mostly waits (sched_yield was a third of
 * C5's quick run), so such fits run with one BLAS thread. OpenBLAS splits
 * its level-3 work by rows and columns of the result, not along the sums, so
 * the values do not depend on it (measured on C5's tables). OpenBLAS's own
 * functions are looked up at run time: the library builds without it. */
#define BLAS_ONE_THREAD_WORK (1.0 * (1 << 26))

int gmm_blas_threads_limit(size_t n, size_t d)
{
  double rows = n < BLOCK ? (double)n : BLOCK;
  if (rows * (double)d * (double)d >= BLAS_ONE_THREAD_WORK) return 0;
  return nl_parallel_blas_limit();
}


void gmm_buffers_init(buffers *w, size_t n, size_t d, size_t kcap, int threads)
{
  w->nb = n < BLOCK ? n : BLOCK;
  w->kcap = kcap;
  w->threads = threads;
  w->nt = nl_parallel_threads((size_t)-1, threads);
  w->R = nl_xmalloc(n * kcap * sizeof(double));
  for (int t = 0; t < w->nt; t++) {
    w->y[t] = nl_xmalloc(w->nb * d * sizeof(double));
    w->z[t] = nl_xmalloc(w->nb * d * sizeof(double));
  }
  w->rmax = nl_xmalloc(kcap * sizeof(double));
  w->bad = nl_xmalloc(kcap * sizeof(int));
}

void gmm_buffers_free(buffers *w)
{
  free(w->R); free(w->rmax); free(w->bad);
  for (int t = 0; t < w->nt; t++) { free(w->y[t]); free(w->z[t]); }
}

void nl_gmm_options_default(nl_gmm_options *o)
{
  o->covariance = NL_GMM_FULL;
  o->tol = 1e-3;
  o->reg_covar = 1e-6;
  o->max_iter = 100;
  o->seed = 0;
  o->init_labels = NULL;
  o->threads = 1;
  o->memo = NULL;
}

/* sklearn's _n_parameters: covariance entries, then means and weights. */
size_t nl_gmm_nparams(size_t k, size_t d, nl_gmm_covariance covariance)
{
  size_t cov = covariance == NL_GMM_FULL ? k * d * (d + 1) / 2
             : covariance == NL_GMM_TIED ? d * (d + 1) / 2
             : covariance == NL_GMM_DIAG ? k * d
             : k;
  return cov + k * d + k - 1;
}

static const char *cov_names[] = {"full", "diag", "tied", "spherical"};

const char *nl_gmm_covariance_name(nl_gmm_covariance c) { return cov_names[c]; }

nl_status nl_gmm_covariance_parse(const char *name, nl_gmm_covariance *c, nl_error *err)
{
  for (int i = 0; i < 4; i++)
    if (!strcmp(name, cov_names[i])) { *c = (nl_gmm_covariance)i; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown covariance type '%s' (full, diag, tied or spherical)",
                 name);
}

/* ---- E-step ---------------------------------------------------------------- */

/* log det Sigma_k / 2 = sum log diag(L_k). */
static double half_logdet(const nl_gmm *g, size_t k)
{
  double s = 0.0;
  const double *c = g->chol + k * cov_size(g);
  for (size_t j = 0; j < g->d; j++)
    s += log(full_storage(g->covariance) ? c[j * g->d + j] : c[j]);
  return s;
}

/* lp[i*K + k] = log w_k + log N(x_i; mu_k, Sigma_k) for the rows of one block
 * and one component k. Full: Y = (X_b - 1 mu_k^T) L_k^{-T}, |y_i|^2 by rows. */
static void block_log_prob(const nl_gmm *g, size_t k, const double *xb, size_t nb, double *y, double *lp)
{
  size_t d = g->d, K = g->k;
  double c0 = -0.5 * (double)d * log(NL_TWO_PI);
  const double *mu = g->means + k * d, *c = g->chol + k * cov_size(g);
  double base = c0 - half_logdet(g, k) + log(g->weights[k]);
  for (size_t i = 0; i < nb; i++)
    for (size_t j = 0; j < d; j++) y[i * d + j] = xb[i * d + j] - mu[j];
  if (full_storage(g->covariance)) {
    /* Y = (X_b - mu) L^{-T}: a multiplication by the stored inverse runs
     * about 3x faster in OpenBLAS than the equivalent dtrsm */
    gsl_matrix_view Y = gsl_matrix_view_array(y, nb, d);
    gsl_matrix_const_view P = gsl_matrix_const_view_array(g->prec + k * d * d, d, d);
    gsl_blas_dtrmm(CblasRight, CblasLower, CblasTrans, CblasNonUnit, 1.0, &P.matrix, &Y.matrix);
  } else {
    for (size_t i = 0; i < nb; i++)
      for (size_t j = 0; j < d; j++) y[i * d + j] /= c[j];
  }
  for (size_t i = 0; i < nb; i++) lp[i * K + k] = base - 0.5 * nl_cluster_sumsq(y + i * d, d);
}

/* Log-sum-exp of one row; turns the row into responsibilities if resp. */
static double row_lse(double *row, size_t K, int resp)
{
  double m = -INFINITY, s = 0.0;
  for (size_t k = 0; k < K; k++) m = fmax(m, row[k]);
  for (size_t k = 0; k < K; k++) s += exp(row[k] - m);
  double lse = m + log(s);
  if (resp)
    for (size_t k = 0; k < K; k++) row[k] = exp(row[k] - lse);
  return lse;
}

/* The E-step's items: (block, component) pairs, block-major; each writes
 * only its own column of its block's rows of lp, with its thread's y. */
typedef struct { const nl_gmm *g; const double *x; size_t n; double *lp; double *const *y; } estep_job;

static void estep_item(void *ctx, size_t item, int t)
{
  const estep_job *j = ctx;
  size_t K = j->g->k, d = j->g->d, i0 = item / K * BLOCK, k = item % K;
  size_t nb = j->n - i0 < BLOCK ? j->n - i0 : BLOCK;
  block_log_prob(j->g, k, j->x + i0 * d, nb, j->y[t], j->lp + i0 * K);
}

/* Sum over rows of log p(x_i). R (n x K, may be NULL) gets responsibilities,
 * logp (may be NULL) each log p(x_i). The log-densities come from threads
 * threads (w's scratch; w NULL: one thread, own scratch); the sums run in
 * row order afterwards, so the result does not depend on the threads. */
static double e_step(const nl_gmm *g, const double *x, size_t n, double *R, double *logp,
                     buffers *w)
{
  size_t K = g->k, d = g->d, nb0 = n < BLOCK ? n : BLOCK, nblk = (n + BLOCK - 1) / BLOCK;
  double *own = NULL, *const *y = w ? w->y : &own;
  if (!w) own = nl_xmalloc(nb0 * d * sizeof(double));
  double *lp = R ? R : w ? w->R : nl_xmalloc(n * K * sizeof(double));   /* w->R: n x kcap >= n x K */
  estep_job j = {g, x, n, lp, y};
  nl_parallel_for(nblk * K, w ? w->threads : 1, estep_item, &j);
  double total = 0.0;
  for (size_t i = 0; i < n; i++) {
    double l = row_lse(lp + i * K, K, R != NULL);
    if (logp) logp[i] = l;
    total += l;
  }
  free(own);
  if (!R && !w) free(lp);
  return total;
}

/* ---- M-step ---------------------------------------------------------------- */

/* Responsibilities below SKIP times the component's largest are left out
 * of its covariance. Such a row lies far out (Mahalanobis^2 > 92 beyond the
 * closest row), so r |x - mu|^2 is tiny too: with n rows the relative change
 * of Sigma_k is below n * SKIP * (its Mahalanobis^2), < 1e-13 for n = 10^4;
 * EM's own tolerance is 1e-3 on the log-likelihood. On clustered data this
 * skips 90% of the rows and makes the M-step several times faster. */
#define SKIP 1e-20

/* Sigma_k (lower triangle) = sum_i r_ik (x_i - mu)(x_i - mu)^T, by dsyrk on
 * blocks of sqrt(r_ik)(x_i - mu), rows with r_ik < rmin left out. The first
 * block's dsyrk has beta = 0 (it overwrites the triangle: 0 + s = s, the same
 * value as zero-filling first), so S is not zero-filled; zbl = rows of z. */
static void scatter_full(const double *x, size_t n, size_t d, const double *R, size_t K,
                         size_t k, const double *mu, double rmin, double *z, size_t zbl, double *S)
{
  gsl_matrix_view C = gsl_matrix_view_array(S, d, d);
  double beta = 0.0;
  size_t nb = 0;
  for (size_t i = 0; i <= n; i++) {
    if (i < n && R[i * K + k] > rmin) {
      double s = sqrt(R[i * K + k]);
      for (size_t j = 0; j < d; j++) z[nb * d + j] = s * (x[i * d + j] - mu[j]);
      nb++;
    }
    if (nb > 0 && (nb == zbl || i == n)) {
      gsl_matrix_view Z = gsl_matrix_view_array(z, nb, d);
      gsl_blas_dsyrk(CblasLower, CblasTrans, 1.0, &Z.matrix, beta, &C.matrix);
      beta = 1.0;
      nb = 0;
    }
  }
  if (beta == 0.0)   /* no row above rmin: an empty scatter */
    for (size_t i = 0; i < d; i++) memset(S + i * d, 0, (i + 1) * sizeof(double));
}

/* Cholesky of covariance k into g->chol (and its inverse into g->prec);
 * 1 on failure. GSL's default error handler aborts, so it is off for the
 * M-step (nl_stats_gsl_quiet_begin). */
static int factorize_one(nl_gmm *g, size_t k)
{
  size_t d = g->d, cs = cov_size(g);
  double *c = g->chol + k * cs;
  memcpy(c, g->covs + k * cs, cs * sizeof(double));
  int bad = 0;
  if (full_storage(g->covariance)) {
    gsl_matrix_view L = gsl_matrix_view_array(c, d, d);
    bad = gsl_linalg_cholesky_decomp1(&L.matrix) != GSL_SUCCESS;
    for (size_t i = 0; i < d; i++)
      for (size_t j = i + 1; j < d; j++) c[i * d + j] = 0.0;
    if (!bad) {   /* prec = L^{-1}, lower triangular */
      double *P = g->prec + k * cs;
      memcpy(P, c, cs * sizeof(double));
      gsl_matrix_view Pv = gsl_matrix_view_array(P, d, d);
      gsl_linalg_tri_invert(CblasLower, CblasNonUnit, &Pv.matrix);
    }
  } else {
    for (size_t j = 0; j < d; j++) { bad |= !(c[j] > 0.0); c[j] = sqrt(c[j]); }
  }
  for (size_t j = 0; j < cs && !bad; j++) bad = !isfinite(c[j]);
  return bad;
}

/* The M-step's items: component k's covariance from its responsibilities
 * (scatter with its thread's z) and its factor; each writes only component
 * k's arrays and bad[k]. */
typedef struct { nl_gmm *g; const double *x; size_t n; const double *R; double reg; buffers *w; } mstep_job;

static void mstep_item(void *ctx, size_t k, int t)
{
  const mstep_job *j = ctx;
  nl_gmm *g = j->g;
  size_t K = g->k, d = g->d, n = j->n, cs = cov_size(g);
  const double *x = j->x, *R = j->R;
  double nk = g->weights[k], *mu = g->means + k * d, *S = g->covs + k * cs;
  for (size_t q = 0; q < d; q++) mu[q] /= nk;
  if (g->covariance == NL_GMM_TIED) {
    /* the raw scatter: m_step pools the components' and factors once */
    scatter_full(x, n, d, R, K, k, mu, SKIP * j->w->rmax[k], j->w->z[t], j->w->nb, S);
    j->w->bad[k] = 0;
    return;
  }
  if (full_storage(g->covariance)) {
    scatter_full(x, n, d, R, K, k, mu, SKIP * j->w->rmax[k], j->w->z[t], j->w->nb, S);
    for (size_t i = 0; i < d; i++)
      for (size_t q = 0; q <= i; q++) S[q * d + i] = S[i * d + q] /= nk;
    for (size_t q = 0; q < d; q++) S[q * d + q] += j->reg;
  } else {
    memset(S, 0, d * sizeof(double));
    for (size_t i = 0; i < n; i++)
      for (size_t q = 0; q < d; q++) {
        double v = x[i * d + q] - mu[q];
        S[q] += R[i * K + k] * v * v;
      }
    for (size_t q = 0; q < d; q++) S[q] = S[q] / nk + j->reg;
    if (g->covariance == NL_GMM_SPHERICAL) {   /* sklearn: the diagonal's mean */
      double m = 0.0;
      for (size_t q = 0; q < d; q++) m += S[q];
      for (size_t q = 0; q < d; q++) S[q] = m / (double)d;
    }
  }
  j->w->bad[k] = factorize_one(g, k);
}

/* Tied: Sigma = sum_k scatter_k / sum_k N_k + reg_covar I (sklearn's
 * _estimate_gaussian_covariances_tied, the pooled within-component
 * covariance), into every component; its factor once, copied. The
 * weights still hold N_k here. */
static void pool_tied(nl_gmm *g, double reg, buffers *w)
{
  size_t K = g->k, d = g->d, cs = d * d;
  double nsum = 0.0, *S = g->covs;
  for (size_t k = 0; k < K; k++) nsum += g->weights[k];
  for (size_t k = 1; k < K; k++)
    for (size_t i = 0; i < d; i++)
      for (size_t q = 0; q <= i; q++) S[i * d + q] += g->covs[k * cs + i * d + q];
  for (size_t i = 0; i < d; i++)
    for (size_t q = 0; q <= i; q++) S[q * d + i] = S[i * d + q] /= nsum;
  for (size_t q = 0; q < d; q++) S[q * d + q] += reg;
  w->bad[0] = factorize_one(g, 0);
  for (size_t k = 1; k < K; k++) {
    memcpy(g->covs + k * cs, S, cs * sizeof(double));
    memcpy(g->chol + k * cs, g->chol, cs * sizeof(double));
    memcpy(g->prec + k * cs, g->prec, cs * sizeof(double));
    w->bad[k] = w->bad[0];
  }
}

/* Weights, means, covariances from responsibilities R (sklearn's
 * _estimate_gaussian_parameters); weights N_k/n at initialisation
 * (normalise = 0) and N_k / sum N_k afterwards, as sklearn does. The
 * components' covariances and factors run on w's threads; NL_ENUM names
 * the first component (in order) whose covariance is not positive
 * definite, as a serial loop would. */
static nl_status m_step(nl_gmm *g, const double *x, size_t n, const double *R, double reg,
                        int normalise, buffers *w, nl_error *err)
{
  size_t K = g->k, d = g->d;
  double total = 0.0;
  double *rmax = w->rmax;
  for (size_t k = 0; k < K; k++) { g->weights[k] = 10 * DBL_EPSILON; rmax[k] = 0.0; }
  for (size_t i = 0; i < n; i++)
    for (size_t k = 0; k < K; k++) {
      g->weights[k] += R[i * K + k];
      rmax[k] = fmax(rmax[k], R[i * K + k]);
    }
  gsl_matrix_const_view Rv = gsl_matrix_const_view_array(R, n, K);
  gsl_matrix_const_view Xv = gsl_matrix_const_view_array(x, n, d);
  gsl_matrix_view M = gsl_matrix_view_array(g->means, K, d);
  gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &Rv.matrix, &Xv.matrix, 0.0, &M.matrix);
  mstep_job j = {g, x, n, R, reg, w};
  nl_stats_gsl_quiet_begin();
  nl_parallel_for(K, w->threads, mstep_item, &j);
  if (g->covariance == NL_GMM_TIED) pool_tied(g, reg, w);
  nl_stats_gsl_quiet_end();
  for (size_t k = 0; k < K; k++) total += g->weights[k];
  for (size_t k = 0; k < K; k++) g->weights[k] /= normalise ? total : (double)n;
  for (size_t k = 0; k < K; k++)
    if (w->bad[k])
      return nl_fail(err, NL_ENUM, "component %zu of %zu: covariance is not positive definite "
                     "(too few points in it?); increase reg_covar or use fewer components",
                     k + 1, g->k);
  return NL_OK;
}

/* ---- fitting ------------------------------------------------------------------- */

nl_status nl_gmm_options_check(const nl_gmm_options *o, nl_error *err)
{
  /* an infinite tol stops EM after one step, an infinite reg_covar makes
   * every covariance singular: refused as `stat gmm` refuses them */
  if (!isfinite(o->tol)) return nl_fail(err, NL_EINVAL, "--tol: %g is not a finite number", o->tol);
  if (!isfinite(o->reg_covar))
    return nl_fail(err, NL_EINVAL, "--reg-covar: %g is not a finite number", o->reg_covar);
  if (!(o->tol >= 0.0 && o->tol <= NL_GMM_MAX_TOL))
    return nl_fail(err, NL_EINVAL, "--tol: %g is outside [0, %g]", o->tol, NL_GMM_MAX_TOL);
  if (!(o->reg_covar >= 0.0 && o->reg_covar <= NL_GMM_MAX_TOL))
    return nl_fail(err, NL_EINVAL, "--reg-covar: %g is outside [0, %g]", o->reg_covar, NL_GMM_MAX_TOL);
  if (o->max_iter < 1 || o->max_iter > NL_GMM_MAX_ITER)
    return nl_fail(err, NL_EINVAL, "--max-iter: %zu is outside [1, %d]", o->max_iter, NL_GMM_MAX_ITER);
  return NL_OK;
}

nl_status gmm_check_fit_args(const nl_gmm *g, const double *x, size_t n,
                                const nl_gmm_options *o, nl_error *err)
{
  if (n < 2) return nl_fail(err, NL_EINVAL, "a mixture needs at least 2 rows, got %zu", n);
  if (g->k < 1 || g->k > n)
    return nl_fail(err, NL_EINVAL, "%zu components for %zu rows: need 1 <= k <= rows", g->k, n);
  nl_status s = nl_gmm_check_size(n, g->d, g->k, g->covariance, err);
  if (s) return s;
  if (o->covariance != g->covariance)
    return nl_fail(err, NL_EINVAL, "options ask for another covariance type than the model has");
  if (nl_gmm_options_check(o, err)) return NL_EINVAL;
  for (size_t i = 0; i < n * g->d; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "row %zu, column %zu is not finite", i / g->d + 1, i % g->d + 1);
  if (o->init_labels)
    for (size_t i = 0; i < n; i++)
      if (o->init_labels[i] < 0 || (size_t)o->init_labels[i] >= g->k)
        return nl_fail(err, NL_EINVAL, "initial label %d of row %zu is not in 0..%zu",
                       o->init_labels[i], i + 1, g->k - 1);
  return NL_OK;
}

/* EM on g (k components) with the buffers of w (kcap >= k). */
nl_status gmm_fit_buffers(nl_gmm *g, const double *x, size_t n, const nl_gmm_options *o,
                        buffers *w, nl_error *err)
{
  nl_status s;
  size_t K = g->k;
  double *R = w->R;
  memset(R, 0, n * K * sizeof(double));
  int *lab = o->init_labels ? NULL : nl_xmalloc(n * sizeof(int));
  if (lab) gmm_kmeans_labels(x, n, g->d, K, o->seed, lab);
  const int *labels = lab ? lab : o->init_labels;
  for (size_t i = 0; i < n; i++) R[i * K + (size_t)labels[i]] = 1.0;
  free(lab);
  s = m_step(g, x, n, R, o->reg_covar, 0, w, err);
  double lower = -INFINITY;
  g->converged = 0;
  g->iterations = 0;
  for (size_t it = 1; it <= o->max_iter && !s; it++) {
    double prev = lower;
    lower = e_step(g, x, n, R, NULL, w) / (double)n;
    s = m_step(g, x, n, R, o->reg_covar, 1, w, err);
    g->iterations = it;
    if (fabs(lower - prev) < o->tol) { g->converged = 1; break; }
  }
  if (s) return s;
  g->n = n;
  g->loglik = e_step(g, x, n, NULL, NULL, w);
  if (!isfinite(g->loglik))
    return nl_fail(err, NL_ENUM, "the log-likelihood is not finite; increase reg_covar");
  g->aic = -2.0 * g->loglik + 2.0 * (double)g->nparams;
  g->bic = -2.0 * g->loglik + (double)g->nparams * log((double)n);
  return NL_OK;
}

nl_status nl_gmm_fit(nl_gmm *g, const double *x, size_t n, const nl_gmm_options *o,
                     nl_error *err)
{
  nl_status s = gmm_check_fit_args(g, x, n, o, err);
  if (s) return s;
  buffers w;
  gmm_buffers_init(&w, n, g->d, g->k, o->threads);
  int threads = gmm_blas_threads_limit(n, g->d);
  s = gmm_fit_buffers(g, x, n, o, &w, err);
  nl_parallel_blas_restore(threads);
  gmm_buffers_free(&w);
  return s;
}

nl_status nl_gmm_loglik(const nl_gmm *g, const double *x, size_t n, double *total,
                        double *logp, nl_error *err)
{
  for (size_t i = 0; i < n * g->d; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "row %zu, column %zu is not finite", i / g->d + 1, i % g->d + 1);
  int threads = gmm_blas_threads_limit(n, g->d);
  *total = e_step(g, x, n, NULL, logp, NULL);
  nl_parallel_blas_restore(threads);
  return NL_OK;
}

nl_status nl_gmm_predict(const nl_gmm *g, const double *x, size_t n, int *labels, nl_error *err)
{
  for (size_t i = 0; i < n * g->d; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "row %zu, column %zu is not finite", i / g->d + 1,
                     i % g->d + 1);
  size_t K = g->k;
  double *R = nl_xmalloc(n * K * sizeof(double));
  int threads = gmm_blas_threads_limit(n, g->d);
  e_step(g, x, n, R, NULL, NULL);
  nl_parallel_blas_restore(threads);
  for (size_t i = 0; i < n; i++) {   /* the first of equal maxima, as numpy's argmax */
    size_t best = 0;
    for (size_t k = 1; k < K; k++)
      if (R[i * K + k] > R[i * K + best]) best = k;
    labels[i] = (int)best;
  }
  free(R);
  return NL_OK;
}

void nl_gmm_sample(const nl_gmm *g, gsl_rng *rng, size_t n, double *out, int *labels)
{
  size_t d = g->d, cs = cov_size(g);
  gsl_ran_discrete_t *pick = gsl_ran_discrete_preproc(g->k, g->weights);
  double *z = nl_xmalloc(d * sizeof(double));
  for (size_t i = 0; i < n; i++) {
    size_t k = gsl_ran_discrete(rng, pick);
    const double *c = g->chol + k * cs, *mu = g->means + k * d;
    for (size_t j = 0; j < d; j++) z[j] = gsl_ran_gaussian_ziggurat(rng, 1.0);
    for (size_t r = 0; r < d; r++) {   /* x = mu + L z */
      double v = mu[r];
      if (full_storage(g->covariance))
        for (size_t j = 0; j <= r; j++) v += c[r * d + j] * z[j];
      else
        v += c[r] * z[r];
      out[i * d + r] = v;
    }
    if (labels) labels[i] = (int)k;
  }
  free(z);
  gsl_ran_discrete_free(pick);
}

