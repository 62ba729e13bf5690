/* nl_gmm.c - EM for Gaussian mixtures (scikit-learn 1.2's GaussianMixture,
 * sklearn/mixture/_gaussian_mixture.py, on level-3 BLAS). */
#define _GNU_SOURCE   /* RTLD_DEFAULT */
#include "stats/nl_gmm.h"
#include "stats/nl_stats_gsl.h"
#include "stats/nl_cluster.h"
#include "base/nl_parallel.h"

#include <float.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_randist.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* Points per block in the E- and M-steps: a 1024 x d block (d = 81: 660 KB)
 * stays in L2 while dtrsm/dsyrk work on it. */
#define BLOCK 1024

/* ---- OpenBLAS threads ----------------------------------------------------- */

/* EM's BLAS calls work on one component's block at a time: at most 1024
 * rows by d columns against a d x d factor. Below 2^26 multiply-adds per
 * call OpenBLAS's second thread mostly waits (sched_yield was a third of
 * C5's quick run), so such fits run with one BLAS thread. OpenBLAS splits
 * its level-3 work by rows and columns of the result, not along the sums, so
 * the values do not depend on it (measured on C5's tables). OpenBLAS's own
 * functions are looked up at run time: the library builds without it. */
#define BLAS_ONE_THREAD_WORK (1.0 * (1 << 26))

static int blas_threads_limit(size_t n, size_t d)
{
  double rows = n < BLOCK ? (double)n : BLOCK;
  if (rows * (double)d * (double)d >= BLAS_ONE_THREAD_WORK) return 0;
  return nl_parallel_blas_limit();
}

/* Buffers of one fit (and of a whole AIC path), allocated once: rows per
 * block nb = min(n, BLOCK), components at most kcap. */
typedef struct {
  size_t nb, kcap;
  int threads, nt;   /* o->threads; scratch copies (threads a region can run) */
  double *R;      /* n x kcap responsibilities */
  double *y[NL_PARALLEL_MAX];   /* per thread, nb x d: E-step block */
  double *z[NL_PARALLEL_MAX];   /* per thread, nb x d: M-step block (full covariances) */
  double *rmax;   /* kcap */
  int *bad;       /* kcap: factorisation failed */
} buffers;

static void ws_init(buffers *w, size_t n, size_t d, size_t kcap, int threads)
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

static void ws_free(buffers *w)
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

/* Tied is stored as full with K equal matrices, spherical as diagonal with d
 * equal variances: the E-step, the factors and sampling need no case of
 * their own, and the log-density is sklearn's for either. */
static int full_storage(nl_gmm_covariance c) { return c == NL_GMM_FULL || c == NL_GMM_TIED; }

static size_t cov_size(const nl_gmm *g)
{
  return full_storage(g->covariance) ? g->d * g->d : g->d;
}

/* K d^2 arrays (covariances, factors, inverses): several MB each, and a
 * C5 run fits about a hundred AIC paths. Fresh memory for each path made a
 * third of a quick C5 run page faults and page zeroing, so a caller that
 * fits many paths passes a workspace (o->workspace) that keeps the arrays
 * after nl_gmm_free for the next model: at most CACHE_SLOTS arrays,
 * CACHE_MAX bytes, behind a mutex, so the threads of one run share it.
 * Without one, the arrays are malloc'd and freed.
 * They are not advised onto 2 MB pages (MADV_HUGEPAGE): on this project's
 * machines (2-core VMs) a fresh 2 MB page cost the kernel several times
 * what 512 small ones do (C5's quick run: 2.62 s of system time with the
 * advice against 0.80 s without; the BLAS calls stream through the
 * arrays, so small pages' TLB misses do not show). A freed array that
 * finds the cache full pushes out smaller ones (a larger array serves
 * their requests too): C5's quick run alternates 34 MB and 79 MB arrays,
 * and keeping the small ones re-zeroed the large ones' pages for every
 * path. No value is ever read before it is written, so the results do
 * not depend on which memory a model gets. A header in front of each
 * array keeps its size and its workspace. The slots hold what is alive at
 * once: 3 arrays of each of the 2 models an AIC path alternates between,
 * for every thread running a path, plus the memo's models (up to 8 of 3). */
#define GRAIN ((size_t)2 << 20)   /* sizes are rounded to it: a freed array serves a bit more */
#define HEADER 64
#define CACHE_SLOTS 32
#define CACHE_MAX ((size_t)1 << 30)

typedef struct { void *base; size_t bytes; } cached;
struct nl_gmm_workspace {
  pthread_mutex_t lock;
  cached cache[CACHE_SLOTS];
  size_t total;
};
typedef struct { size_t bytes; nl_gmm_workspace *ws; } header;

nl_gmm_workspace *nl_gmm_workspace_alloc(void)
{
  nl_gmm_workspace *w = calloc(1, sizeof *w);
  if (w) pthread_mutex_init(&w->lock, NULL);
  return w;
}

void nl_gmm_workspace_free(nl_gmm_workspace *w)
{
  if (!w) return;
  for (int q = 0; q < CACHE_SLOTS; q++) free(w->cache[q].base);
  pthread_mutex_destroy(&w->lock);
  free(w);
}

size_t nl_gmm_workspace_bytes(const nl_gmm_workspace *w)
{
  return w ? w->total : 0;
}

static double *big_alloc(nl_gmm_workspace *ws, size_t count, int zero)
{
  size_t bytes = HEADER + count * sizeof(double);
  void *base = NULL;
  if (!ws || bytes < 2 * GRAIN) {
    base = zero ? nl_xcalloc(1, bytes) : nl_xmalloc(bytes);
    ws = NULL;
  } else {
    bytes = (bytes + GRAIN - 1) / GRAIN * GRAIN;
    int best = -1;   /* the smallest cached array that is large enough */
    pthread_mutex_lock(&ws->lock);
    for (int q = 0; q < CACHE_SLOTS; q++)
      if (ws->cache[q].base && ws->cache[q].bytes >= bytes &&
          (best < 0 || ws->cache[q].bytes < ws->cache[best].bytes)) best = q;
    if (best >= 0) {
      base = ws->cache[best].base;
      bytes = ws->cache[best].bytes;
      ws->total -= bytes;
      ws->cache[best].base = NULL;
    }
    pthread_mutex_unlock(&ws->lock);
    if (best < 0) base = nl_xmalloc(bytes);
    if (zero) memset((char *)base + HEADER, 0, count * sizeof(double));
  }
  *(header *)base = (header){bytes, ws};
  return (double *)((char *)base + HEADER);
}

static void big_free(double *p)
{
  if (!p) return;
  void *base = (char *)p - HEADER;
  header h = *(header *)base;
  nl_gmm_workspace *ws = h.ws;
  if (ws) {
    pthread_mutex_lock(&ws->lock);
    int kept = 0;
    for (;;) {   /* room for it: smaller arrays make way (a larger one serves their requests too) */
      int freeslot = -1, small = -1;
      for (int q = 0; q < CACHE_SLOTS; q++) {
        if (!ws->cache[q].base) freeslot = q;
        else if (ws->cache[q].bytes < h.bytes && (small < 0 || ws->cache[q].bytes < ws->cache[small].bytes))
          small = q;
      }
      if (freeslot >= 0 && ws->total + h.bytes <= CACHE_MAX) {
        ws->cache[freeslot] = (cached){base, h.bytes};
        ws->total += h.bytes;
        kept = 1;
        break;
      }
      if (small < 0) break;
      free(ws->cache[small].base);
      ws->total -= ws->cache[small].bytes;
      ws->cache[small].base = NULL;
    }
    pthread_mutex_unlock(&ws->lock);
    if (kept) return;
  }
  free(base);
}

/* Room for kcap components; zeroed only when zero (a fit writes every
 * entry, and untouched pages of unzeroed memory cost nothing). */
static nl_gmm *gmm_new(size_t k, size_t kcap, size_t d, nl_gmm_covariance covariance, int zero,
                       nl_gmm_workspace *ws)
{
  nl_gmm *g = nl_xcalloc(1, sizeof *g);
  g->k = k;
  g->d = d;
  g->covariance = covariance;
  size_t cs = cov_size(g);
#define GET(m) (zero ? nl_xcalloc((m), sizeof(double)) : nl_xmalloc((m) * sizeof(double)))
  g->weights = GET(kcap);
  g->means = GET(kcap * d);
  g->covs = big_alloc(ws, kcap * cs, zero);
  g->chol = big_alloc(ws, kcap * cs, zero);
  g->prec = full_storage(covariance) ? big_alloc(ws, kcap * d * d, zero) : NULL;
#undef GET
  g->nparams = nl_gmm_nparams(k, d, covariance);
  return g;
}

nl_gmm *nl_gmm_alloc(size_t k, size_t d, nl_gmm_covariance covariance)
{
  return gmm_new(k, k, d, covariance, 1, NULL);
}

nl_gmm *nl_gmm_alloc_workspace(size_t k, size_t d, nl_gmm_covariance covariance,
                               nl_gmm_workspace *w)
{
  return gmm_new(k, k, d, covariance, 1, w);
}

double nl_gmm_bytes(size_t n, size_t d, size_t k, nl_gmm_covariance covariance)
{
  double N = (double)n, D = (double)d, K = (double)k;
  double cs = full_storage(covariance) ? D * D : D;
  double model = K * (1 + D + 3 * cs);
  return sizeof(double) * (2 * N * K + N + 2 * model + BLOCK * (2 * D + K)) + sizeof(int) * N;
}

nl_status nl_gmm_check_size(size_t n, size_t d, size_t k, nl_gmm_covariance covariance,
                            nl_error *err)
{
  double need = nl_gmm_bytes(n, d, k, covariance);
  if (nl_mem_fits(need)) return NL_OK;
  char b1[32], b2[32];
  return nl_fail(err, NL_ENOMEM, "%zu rows of %zu columns with %zu components need %s; %s is available",
                 n, d, k, nl_format_bytes(b1, need), nl_format_bytes(b2, nl_mem_available()));
}

void nl_gmm_free(nl_gmm *g)
{
  if (!g) return;
  free(g->weights); free(g->means);
  big_free(g->covs); big_free(g->chol); big_free(g->prec);
  free(g);
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

/* ---- initialisation: k-means++ and Lloyd ------------------------------------ */

/* Squared distances of every row to every centre, D = |x|^2 - 2 X C^T + |c|^2
 * (dgemm; only used to pick the nearest centre). */
static void sq_dists(const double *x, size_t n, size_t d, const double *c, size_t K,
                     const double *xx, double *D)
{
  gsl_matrix_const_view Xv = gsl_matrix_const_view_array(x, n, d);
  gsl_matrix_const_view Cv = gsl_matrix_const_view_array(c, K, d);
  gsl_matrix_view Dv = gsl_matrix_view_array(D, n, K);
  gsl_blas_dgemm(CblasNoTrans, CblasTrans, -2.0, &Xv.matrix, &Cv.matrix, 0.0, &Dv.matrix);
  for (size_t k = 0; k < K; k++) {
    double cc = 0.0;
    for (size_t j = 0; j < d; j++) cc += c[k * d + j] * c[k * d + j];
    for (size_t i = 0; i < n; i++) D[i * K + k] += xx[i] + cc;
  }
}

/* k-means++ seeding: each new centre is a row drawn with probability
 * proportional to its squared distance to the nearest centre so far. */
static void kmeanspp(const double *x, size_t n, size_t d, size_t K, gsl_rng *rng, double *c)
{
  double *dmin = nl_xmalloc(n * sizeof(double)), total = 0.0;
  size_t first = gsl_rng_uniform_int(rng, n);
  memcpy(c, x + first * d, d * sizeof(double));
  for (size_t i = 0; i < n; i++) {
    double s = 0.0;
    for (size_t j = 0; j < d; j++) s += (x[i * d + j] - c[j]) * (x[i * d + j] - c[j]);
    dmin[i] = s;
  }
  for (size_t k = 1; k < K; k++) {
    total = 0.0;
    for (size_t i = 0; i < n; i++) total += dmin[i];
    double r = gsl_rng_uniform(rng) * total;
    size_t pick = n - 1;
    for (size_t i = 0; i < n; i++) { r -= dmin[i]; if (r < 0.0) { pick = i; break; } }
    if (total <= 0.0) pick = gsl_rng_uniform_int(rng, n);   /* all points on centres */
    memcpy(c + k * d, x + pick * d, d * sizeof(double));
    for (size_t i = 0; i < n; i++) {
      double s = 0.0;
      for (size_t j = 0; j < d; j++) s += (x[i * d + j] - c[k * d + j]) * (x[i * d + j] - c[k * d + j]);
      dmin[i] = fmin(dmin[i], s);
    }
  }
  free(dmin);
}

/* Lloyd's k-means from k-means++ seeds; stops when no label changes or
 * after 300 iterations (sklearn's max_iter). Writes labels. */
static void kmeans_labels(const double *x, size_t n, size_t d, size_t K, unsigned long seed,
                          int *labels)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "gmm.kmeans", 0));
  double *c = nl_xmalloc(K * d * sizeof(double)), *D = nl_xmalloc(n * K * sizeof(double));
  double *xx = nl_xmalloc(n * sizeof(double)), *cnt = nl_xmalloc(K * sizeof(double));
  double *old = nl_xmalloc(K * d * sizeof(double));
  for (size_t i = 0; i < n; i++) {
    xx[i] = 0.0;
    for (size_t j = 0; j < d; j++) xx[i] += x[i * d + j] * x[i * d + j];
    labels[i] = -1;
  }
  kmeanspp(x, n, d, K, rng, c);
  for (int it = 0; it < 300; it++) {
    sq_dists(x, n, d, c, K, xx, D);
    size_t changed = 0;
    for (size_t i = 0; i < n; i++) {
      size_t best = 0;
      for (size_t k = 1; k < K; k++) if (D[i * K + k] < D[i * K + best]) best = k;
      changed += labels[i] != (int)best;
      labels[i] = (int)best;
    }
    if (!changed) break;
    memset(cnt, 0, K * sizeof(double));
    memcpy(old, c, K * d * sizeof(double));
    memset(c, 0, K * d * sizeof(double));
    for (size_t i = 0; i < n; i++) {
      cnt[labels[i]] += 1.0;
      for (size_t j = 0; j < d; j++) c[labels[i] * d + j] += x[i * d + j];
    }
    for (size_t k = 0; k < K; k++)   /* an emptied cluster keeps its centre */
      for (size_t j = 0; j < d; j++) c[k * d + j] = cnt[k] > 0 ? c[k * d + j] / cnt[k] : old[k * d + j];
  }
  free(c); free(D); free(xx); free(cnt); free(old);
  gsl_rng_free(rng);
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

static nl_status check_fit_args(const nl_gmm *g, const double *x, size_t n,
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
static nl_status fit_ws(nl_gmm *g, const double *x, size_t n, const nl_gmm_options *o,
                        buffers *w, nl_error *err)
{
  nl_status s;
  size_t K = g->k;
  double *R = w->R;
  memset(R, 0, n * K * sizeof(double));
  int *lab = o->init_labels ? NULL : nl_xmalloc(n * sizeof(int));
  if (lab) kmeans_labels(x, n, g->d, K, o->seed, lab);
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
  nl_status s = check_fit_args(g, x, n, o, err);
  if (s) return s;
  buffers w;
  ws_init(&w, n, g->d, g->k, o->threads);
  int threads = blas_threads_limit(n, g->d);
  s = fit_ws(g, x, n, o, &w, err);
  nl_parallel_blas_restore(threads);
  ws_free(&w);
  return s;
}

nl_status nl_gmm_loglik(const nl_gmm *g, const double *x, size_t n, double *total,
                        double *logp, nl_error *err)
{
  for (size_t i = 0; i < n * g->d; i++)
    if (!isfinite(x[i]))
      return nl_fail(err, NL_EINVAL, "row %zu, column %zu is not finite", i / g->d + 1, i % g->d + 1);
  int threads = blas_threads_limit(n, g->d);
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
  int threads = blas_threads_limit(n, g->d);
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

/* ---- the memo of fits ------------------------------------------------------ */

/* Models kept at most, their bytes, and the largest kept: a copy costs its
 * pages' first touch, so only models cheaper to copy than to fit are kept
 * (C5's 152-column mixtures, 23 MB at K = 42, not its 484-column ones). */
#define MEMO_MODELS 8
#define MEMO_MODEL_BYTES ((size_t)192 << 20)
#define MEMO_ONE_MODEL ((size_t)32 << 20)
#define MEMO_MIN_ROWS 1000   /* fewer rows: a fit is about as cheap as the copy */

typedef struct { double *x; size_t n, d; unsigned long long hash; } memo_rows;
typedef struct { size_t rows, k; unsigned long seed; nl_gmm_covariance cov; double tol, reg; size_t max_iter; } memo_key;
typedef struct { memo_key key; nl_gmm_step step; } memo_step;
typedef struct { memo_key key; nl_gmm *g; size_t bytes; } memo_model;

struct nl_gmm_memo {
  pthread_mutex_t lock;
  memo_rows *rows;
  size_t nrows, caprows;
  memo_step *steps;
  size_t nsteps, capsteps;
  memo_model models[MEMO_MODELS];   /* oldest first */
  size_t nmodels, model_bytes;
  size_t fitted, reused;
};

nl_gmm_memo *nl_gmm_memo_alloc(void)
{
  nl_gmm_memo *m = nl_xcalloc(1, sizeof *m);
  pthread_mutex_init(&m->lock, NULL);
  return m;
}

void nl_gmm_memo_free(nl_gmm_memo *m)
{
  if (!m) return;
  for (size_t i = 0; i < m->nrows; i++) free(m->rows[i].x);
  for (size_t i = 0; i < m->nmodels; i++) nl_gmm_free(m->models[i].g);
  free(m->rows); free(m->steps);
  pthread_mutex_destroy(&m->lock);
  free(m);
}

void nl_gmm_memo_counts(const nl_gmm_memo *m, size_t *fitted, size_t *reused)
{
  *fitted = m ? m->fitted : 0;
  *reused = m ? m->reused : 0;
}

/* FNV-1a over the bytes: only to skip most comparisons; equality is memcmp. */
static unsigned long long rows_hash(const double *x, size_t count)
{
  const unsigned char *b = (const unsigned char *)x;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < count * sizeof(double); i += 8) {   /* 8 bytes a step */
    unsigned long long v;
    memcpy(&v, b + i, 8);
    h = (h ^ v) * 1099511628211ULL;
  }
  return h;
}

/* Index of the rows x (n x d) in the memo, added (copied) if new. */
static size_t memo_rows_index(nl_gmm_memo *m, const double *x, size_t n, size_t d)
{
  unsigned long long h = rows_hash(x, n * d);
  pthread_mutex_lock(&m->lock);
  size_t i;
  for (i = 0; i < m->nrows; i++)
    if (m->rows[i].n == n && m->rows[i].d == d && m->rows[i].hash == h && !memcmp(m->rows[i].x, x, n * d * sizeof(double))) break;
  if (i == m->nrows) {
    if (m->nrows == m->caprows) {
      m->caprows = m->caprows ? 2 * m->caprows : 16;
      m->rows = nl_xrealloc(m->rows, m->caprows * sizeof *m->rows);
    }
    double *copy = nl_xmalloc(n * d * sizeof(double));
    memcpy(copy, x, n * d * sizeof(double));
    m->rows[m->nrows++] = (memo_rows){copy, n, d, h};
  }
  pthread_mutex_unlock(&m->lock);
  return i;
}

static int key_eq(const memo_key *a, const memo_key *b)
{
  return a->rows == b->rows && a->k == b->k && a->seed == b->seed && a->cov == b->cov &&
         a->tol == b->tol && a->reg == b->reg && a->max_iter == b->max_iter;
}

static int memo_get_step(nl_gmm_memo *m, const memo_key *key, nl_gmm_step *step)
{
  int found = 0;
  pthread_mutex_lock(&m->lock);
  for (size_t i = 0; i < m->nsteps && !found; i++)
    if (key_eq(&m->steps[i].key, key)) { *step = m->steps[i].step; found = 1; }
  if (found) m->reused++;
  pthread_mutex_unlock(&m->lock);
  return found;
}

static void memo_put_step(nl_gmm_memo *m, const memo_key *key, const nl_gmm_step *step)
{
  pthread_mutex_lock(&m->lock);
  m->fitted++;
  int found = 0;
  for (size_t i = 0; i < m->nsteps && !found; i++) found = key_eq(&m->steps[i].key, key);
  if (!found) {
    if (m->nsteps == m->capsteps) {
      m->capsteps = m->capsteps ? 2 * m->capsteps : 64;
      m->steps = nl_xrealloc(m->steps, m->capsteps * sizeof *m->steps);
    }
    m->steps[m->nsteps++] = (memo_step){*key, *step};
  }
  pthread_mutex_unlock(&m->lock);
}

static size_t model_bytes(const nl_gmm *g)
{
  size_t cs = cov_size(g);
  return sizeof(double) * (g->k * (1 + g->d) + g->k * cs * (full_storage(g->covariance) ? 3 : 2));
}

/* A copy of g with exactly g->k components, its arrays from g's workspace. */
static nl_gmm *gmm_clone(const nl_gmm *g)
{
  nl_gmm *c = gmm_new(g->k, g->k, g->d, g->covariance, 0,
                      ((header *)(void *)((char *)g->covs - HEADER))->ws);
  size_t k = g->k, d = g->d, cs = cov_size(g);
  memcpy(c->weights, g->weights, k * sizeof(double));
  memcpy(c->means, g->means, k * d * sizeof(double));
  memcpy(c->covs, g->covs, k * cs * sizeof(double));
  memcpy(c->chol, g->chol, k * cs * sizeof(double));
  if (g->prec) memcpy(c->prec, g->prec, k * d * d * sizeof(double));
  c->n = g->n; c->loglik = g->loglik; c->aic = g->aic; c->bic = g->bic;
  c->nparams = g->nparams; c->iterations = g->iterations; c->converged = g->converged;
  return c;
}

/* A copy of the kept model of key, or NULL. */
static nl_gmm *memo_get_model(nl_gmm_memo *m, const memo_key *key)
{
  nl_gmm *c = NULL;
  pthread_mutex_lock(&m->lock);
  for (size_t i = 0; i < m->nmodels && !c; i++)
    if (key_eq(&m->models[i].key, key)) c = gmm_clone(m->models[i].g);
  pthread_mutex_unlock(&m->lock);
  return c;
}

/* Keeps a copy of g (unless kept already), dropping the oldest beyond the budget. */
static void memo_put_model(nl_gmm_memo *m, const memo_key *key, const nl_gmm *g)
{
  size_t bytes = model_bytes(g);
  if (bytes > MEMO_ONE_MODEL) return;
  pthread_mutex_lock(&m->lock);
  int found = 0;
  for (size_t i = 0; i < m->nmodels && !found; i++) found = key_eq(&m->models[i].key, key);
  if (!found) {
    while (m->nmodels == MEMO_MODELS || m->model_bytes + bytes > MEMO_MODEL_BYTES) {
      nl_gmm_free(m->models[0].g);
      m->model_bytes -= m->models[0].bytes;
      memmove(m->models, m->models + 1, (m->nmodels - 1) * sizeof *m->models);
      m->nmodels--;
    }
    m->models[m->nmodels++] = (memo_model){*key, gmm_clone(g), bytes};
    m->model_bytes += bytes;
  }
  pthread_mutex_unlock(&m->lock);
}

/* The state one AIC path's fits share: the spare model (room for kcap
 * components) and the workspace, set up at the first fit the memo cannot
 * answer. */
typedef struct {
  const double *x;
  size_t n, d, kcap;
  const nl_gmm_options *o;
  nl_gmm *spare;
  buffers w;
  int threads, ready;
} path_fits;

/* Fits K components into the spare model (or a new one) -> *out. */
static nl_status path_fit(path_fits *p, size_t k, nl_gmm **out, nl_error *err)
{
  nl_gmm *g = p->spare ? p->spare : gmm_new(k, p->kcap, p->d, p->o->covariance, 0, p->o->workspace);
  p->spare = NULL;
  g->k = k;
  g->nparams = nl_gmm_nparams(k, p->d, p->o->covariance);
  if (!p->ready) {
    ws_init(&p->w, p->n, p->d, p->kcap, p->o->threads);
    p->threads = blas_threads_limit(p->n, p->d);
    p->ready = 1;
  }
  nl_status s = fit_ws(g, p->x, p->n, p->o, &p->w, err);
  if (s) { nl_gmm_free(g); g = NULL; }
  *out = g;
  return s;
}

nl_status nl_gmm_select_aic(const double *x, size_t n, size_t d, size_t k0, double threshold,
                            size_t k_max, const nl_gmm_options *o, nl_gmm **best,
                            nl_gmm_step *path, size_t *npath, nl_error *err)
{
  *best = NULL;
  *npath = 0;
  if (k0 < 1 || k0 > n || k_max < k0)
    return nl_fail(err, NL_EINVAL, "start K0 = %zu must be in 1..%zu rows (and <= k_max %zu)",
                   k0, n, k_max);
  if (!(threshold >= 0.0)) return nl_fail(err, NL_EINVAL, "AIC threshold must be >= 0");
  nl_status sz = nl_gmm_check_size(n, d, k_max < n ? k_max : n, o->covariance, err);
  if (sz) return sz;
  nl_gmm_options ok = *o;
  ok.init_labels = NULL;   /* labels are for one k; each fit seeds k-means */
  nl_gmm shape = {.k = k0, .d = d, .covariance = o->covariance};
  nl_status s = check_fit_args(&shape, x, n, &ok, err);
  if (s) return s;
  nl_gmm_memo *memo = o->memo;
  memo_key key = {0, 0, o->seed, o->covariance, o->tol, o->reg_covar, o->max_iter};
  if (memo) key.rows = memo_rows_index(memo, x, n, d);
  /* Two models with room for the largest K take turns (the best so far and
   * the one being fitted), and one workspace serves every K: K d^2 arrays
   * are allocated, and their pages touched, once per path, not per K. A K
   * the memo knows gives its path entry without a fit; its model is only
   * needed if the path selects it (bestk without bestg). */
  path_fits p = {x, n, d, k_max < n ? k_max : n, &ok, NULL, {0}, 0, 0};
  size_t bestk = 0;
  nl_gmm *bestg = NULL;
  double bestaic = 0;
  for (size_t k = k0; k <= k_max && k <= n; k++) {
    nl_gmm_step step;
    nl_gmm *g = NULL;
    key.k = k;
    if (!memo || !memo_get_step(memo, &key, &step)) {
      if ((s = path_fit(&p, k, &g, err))) break;
      step = (nl_gmm_step){k, g->loglik, g->aic, g->bic, g->iterations, g->converged};
      if (memo) memo_put_step(memo, &key, &step);
    }
    path[(*npath)++] = step;
    if (bestk && bestaic - step.aic < threshold) { if (g) { nl_gmm_free(p.spare); p.spare = g; } break; }
    if (bestg) { nl_gmm_free(p.spare); p.spare = bestg; }
    bestg = g; bestk = k; bestaic = step.aic;
  }
  if (!s && bestk && !bestg) {   /* the selected K came from the memo */
    key.k = bestk;
    if (!(bestg = memo_get_model(memo, &key))) s = path_fit(&p, bestk, &bestg, err);
  }
  if (!s && memo && bestg && n >= MEMO_MIN_ROWS) { key.k = bestk; memo_put_model(memo, &key, bestg); }
  if (s) { nl_gmm_free(bestg); bestg = NULL; }   /* a failed path returns no model */
  *best = bestg;
  if (p.ready) { nl_parallel_blas_restore(p.threads); ws_free(&p.w); }
  nl_gmm_free(p.spare);
  return s;
}
