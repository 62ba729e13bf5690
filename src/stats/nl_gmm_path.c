/* nl_gmm_path.c - model selection by AIC (Cheng sec. 3.5.3): the path K0,
 * K0 + 1, ... and the memo of fits that AIC paths over the same rows share
 * (nl_gmm.h). */
#include "stats/nl_gmm_internal.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

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
    gmm_buffers_init(&p->w, p->n, p->d, p->kcap, p->o->threads);
    p->threads = gmm_blas_threads_limit(p->n, p->d);
    p->ready = 1;
  }
  nl_status s = gmm_fit_buffers(g, p->x, p->n, p->o, &p->w, err);
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
  nl_status s = gmm_check_fit_args(&shape, x, n, &ok, err);
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
  if (p.ready) { nl_parallel_blas_restore(p.threads); gmm_buffers_free(&p.w); }
  nl_gmm_free(p.spare);
  return s;
}
