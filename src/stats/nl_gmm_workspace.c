/* nl_gmm_workspace.c - models and their arrays: allocation, the size
 * check, copies, and the workspace that keeps freed arrays for the next
 * models (nl_gmm.h). */
#include "stats/nl_gmm_internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

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
nl_gmm *gmm_new(size_t k, size_t kcap, size_t d, nl_gmm_covariance covariance, int zero,
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

/* A copy of g with exactly g->k components, its arrays from g's workspace. */
nl_gmm *gmm_clone(const nl_gmm *g)
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

