/* nl_gmm_internal.h - what the files of the GMM module share (private; not
 * installed): nl_gmm.c (options, EM, the fitted model's calls),
 * nl_gmm_init.c (k-means++ and Lloyd), nl_gmm_workspace.c (models, their
 * arrays and the workspace) and nl_gmm_path.c (the AIC path and its memo).
 * Hidden from the shared library's symbols. */
#ifndef NL_GMM_INTERNAL_H
#define NL_GMM_INTERNAL_H

#include "stats/nl_gmm.h"
#include "base/nl_parallel.h"

#define NL_GMM_HIDDEN __attribute__((visibility("hidden")))

/* Points per block in the E- and M-steps: a 1024 x d block (d = 81: 660 KB)
 * stays in L2 while dtrsm/dsyrk work on it. */
#define BLOCK 1024

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
NL_GMM_HIDDEN void gmm_buffers_init(buffers *w, size_t n, size_t d, size_t kcap, int threads);
NL_GMM_HIDDEN void gmm_buffers_free(buffers *w);

/* Tied is stored as full with K equal matrices, spherical as diagonal with d
 * equal variances: the E-step, the factors and sampling need no case of
 * their own, and the log-density is sklearn's for either. */
static inline int full_storage(nl_gmm_covariance c) { return c == NL_GMM_FULL || c == NL_GMM_TIED; }

static inline size_t cov_size(const nl_gmm *g)
{
  return full_storage(g->covariance) ? g->d * g->d : g->d;
}


/* Room for kcap components, arrays from ws (NULL: malloc); zeroed only
 * when zero. A copy of g with exactly g->k components, from g's workspace. */
NL_GMM_HIDDEN nl_gmm *gmm_new(size_t k, size_t kcap, size_t d, nl_gmm_covariance covariance,
                              int zero, nl_gmm_workspace *ws);
NL_GMM_HIDDEN nl_gmm *gmm_clone(const nl_gmm *g);

/* One BLAS thread for EM's small calls; the count to hand back (nl_gmm.c). */
NL_GMM_HIDDEN int gmm_blas_threads_limit(size_t n, size_t d);
/* The checks of nl_gmm_fit, and EM on g with the buffers of w (kcap >= k). */
NL_GMM_HIDDEN nl_status gmm_check_fit_args(const nl_gmm *g, const double *x, size_t n,
                                           const nl_gmm_options *o, nl_error *err);
NL_GMM_HIDDEN nl_status gmm_fit_buffers(nl_gmm *g, const double *x, size_t n,
                                        const nl_gmm_options *o, buffers *w, nl_error *err);
/* k-means labels of n rows (k-means++ from seed, then Lloyd) (nl_gmm_init.c). */
NL_GMM_HIDDEN void gmm_kmeans_labels(const double *x, size_t n, size_t d, size_t K,
                                     unsigned long seed, int *labels);

#endif
